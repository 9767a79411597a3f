// SPDX-License-Identifier: Apache-2.0
package org.pednav;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.locks.ReentrantReadWriteLock;

/**
 * A pednav engine: one pipeline built from a JSON config, fed with sensor
 * samples, polled for positions, strides and steps. Wraps {@code pn_engine.h}.
 *
 * <p>Processing runs inside the push calls on the caller's thread; the same
 * input and config give bit-identical output. One thread may push while one
 * other thread polls; other calls are serialised by the binding. Close the
 * engine (try-with-resources) to free its native memory; {@link #close()} may
 * be called any number of times, and every other call on a closed engine
 * throws {@link IllegalStateException}.
 *
 * <p>Failures reported by the engine throw {@link PednavException}; a null
 * array throws {@link NullPointerException}, arrays of mismatched length
 * {@link IllegalArgumentException}. Time stamps are nanoseconds on one
 * monotonic clock; units are SI, frames ENU (navigation) and FLU (body).
 */
public final class Engine implements AutoCloseable {
    static {
        NativeLibrary.load();
    }

    /** Record type ids returned by nativePoll (PN_REC_*). */
    private static final int REC_STEP = 6, REC_POSITION = 9, REC_STRIDE = 10;
    /** Scratch layout shared with pednav_jni.c (PNJ_POLL_LONGS, PNJ_POLL_DOUBLES). */
    private static final int POLL_LONGS = 8, POLL_DOUBLES = 24;

    /** pn_engine_t*, 0 once closed. Written only under the write lock. */
    private long handle;
    /** Read-held by every call, write-held by close: no call runs on a freed engine. */
    private final ReentrantReadWriteLock lifetime = new ReentrantReadWriteLock();
    /** Serialises the producer side (push, flush, reset, setStart, describe). */
    private final Object inputLock = new Object();
    /** Serialises the consumer side (poll) and guards the scratch arrays. */
    private final Object outputLock = new Object();
    private final long[] pollLongs = new long[POLL_LONGS];
    private final double[] pollDoubles = new double[POLL_DOUBLES];

    private Engine(long handle) {
        this.handle = handle;
    }

    /**
     * Loads the plugins the config names from {@code pluginDirs} (searched in
     * order for libpnp_*.so) and builds the pipeline of the configured mount.
     *
     * @throws PednavException with {@link PednavException#where()} naming the
     *     config key (a JSON pointer) or the plugin file at fault
     */
    public static Engine create(String configJson, String... pluginDirs) {
        Objects.requireNonNull(configJson, "configJson");
        byte[][] dirs = new byte[pluginDirs == null ? 0 : pluginDirs.length][];
        for (int i = 0; i < dirs.length; ++i)
            dirs[i] = Objects.requireNonNull(pluginDirs[i], "pluginDirs[" + i + "]").getBytes(StandardCharsets.UTF_8);
        long h = nativeCreate(configJson.getBytes(StandardCharsets.UTF_8), dirs);
        if (h == 0) throw new IllegalStateException("pn_engine_create returned no engine and no error");
        return new Engine(h);
    }

    /** The engine library's ABI version: major in the high 16 bits, minor in the low 16. */
    public static int abiVersion() {
        return nativeAbiVersion();
    }

    /** The engine library's version, e.g. "0.1.0". */
    public static String version() {
        return new String(nativeVersion(), StandardCharsets.UTF_8);
    }

    // ---------------------------------------------------------------- input

    /** One IMU sample: specific force (m/s^2) and angular rate (rad/s), body frame (FLU). */
    public void pushImu(long tNs, double ax, double ay, double az, double gx, double gy, double gz) {
        lifetime.readLock().lock();
        try {
            synchronized (inputLock) {
                nativePushImu(live(), tNs, ax, ay, az, gx, gy, gz);
            }
        } finally {
            lifetime.readLock().unlock();
        }
    }

    /**
     * n IMU samples in one native call: {@code tNs[n]}, {@code accel[3n]} and
     * {@code gyro[3n]} as x, y, z per sample. A rejected sample stops the push
     * there with a PednavException whose {@link PednavException#detail()} is
     * its index; the samples before it are processed and kept.
     */
    public void pushImu(long[] tNs, double[] accel, double[] gyro) {
        Objects.requireNonNull(tNs, "tNs");
        Objects.requireNonNull(accel, "accel");
        Objects.requireNonNull(gyro, "gyro");
        if (accel.length != 3L * tNs.length || gyro.length != 3L * tNs.length)
            throw new IllegalArgumentException("accel and gyro must hold 3 values per time stamp: tNs.length="
                    + tNs.length + ", accel.length=" + accel.length + ", gyro.length=" + gyro.length);
        lifetime.readLock().lock();
        try {
            synchronized (inputLock) {
                nativePushImuBulk(live(), tNs, accel, gyro);
            }
        } finally {
            lifetime.readLock().unlock();
        }
    }

    /** One magnetometer sample in microtesla, body frame. */
    public void pushMag(long tNs, double mxUt, double myUt, double mzUt) {
        lifetime.readLock().lock();
        try {
            synchronized (inputLock) {
                nativePushMag(live(), tNs, mxUt, myUt, mzUt);
            }
        } finally {
            lifetime.readLock().unlock();
        }
    }

    /** One barometer sample: static pressure (Pa) and temperature (deg C, NaN when unknown). */
    public void pushBaro(long tNs, double pressurePa, double temperatureC) {
        lifetime.readLock().lock();
        try {
            synchronized (inputLock) {
                nativePushBaro(live(), tNs, pressurePa, temperatureC);
            }
        } finally {
            lifetime.readLock().unlock();
        }
    }

    /** One satellite fix (WGS-84) without velocity or UTC. */
    public void pushGnss(long tNs, double latDeg, double lonDeg, double heightM, double hAccuracyM,
            double vAccuracyM) {
        pushGnss(tNs, latDeg, lonDeg, heightM, hAccuracyM, vAccuracyM, null, 0L);
    }

    /**
     * One satellite fix (WGS-84). {@code velEnuMps} is null or 3 values
     * (east, north, up in m/s); {@code utcNs} is 0 when unknown.
     */
    public void pushGnss(long tNs, double latDeg, double lonDeg, double heightM, double hAccuracyM,
            double vAccuracyM, double[] velEnuMps, long utcNs) {
        if (velEnuMps != null && velEnuMps.length != 3)
            throw new IllegalArgumentException("velEnuMps must hold 3 values, not " + velEnuMps.length);
        boolean hasVel = velEnuMps != null;
        lifetime.readLock().lock();
        try {
            synchronized (inputLock) {
                nativePushGnss(live(), tNs, latDeg, lonDeg, heightM, hAccuracyM, vAccuracyM, hasVel,
                        hasVel ? velEnuMps[0] : 0.0, hasVel ? velEnuMps[1] : 0.0, hasVel ? velEnuMps[2] : 0.0,
                        utcNs);
            }
        } finally {
            lifetime.readLock().unlock();
        }
    }

    // -------------------------------------------------------------- control

    /** End of stream: drains every stage's look-ahead. Pushing afterwards starts a new segment. */
    public void flush() {
        lifetime.readLock().lock();
        try {
            synchronized (inputLock) {
                nativeFlush(live());
            }
        } finally {
            lifetime.readLock().unlock();
        }
    }

    /** Back to the state right after create: plugins reset, queued outputs dropped. */
    public void reset() {
        lifetime.readLock().lock();
        try {
            synchronized (inputLock) {
                synchronized (outputLock) {
                    nativeReset(live());
                }
            }
        } finally {
            lifetime.readLock().unlock();
        }
    }

    /**
     * Start point (ENU metres) and heading (degrees clockwise from north; NaN =
     * from the sensors) for the position filter and map matcher. Call before
     * the first push.
     */
    public void setStart(double x, double y, double z, double headingDeg) {
        lifetime.readLock().lock();
        try {
            synchronized (inputLock) {
                nativeSetStart(live(), x, y, z, headingDeg);
            }
        } finally {
            lifetime.readLock().unlock();
        }
    }

    // --------------------------------------------------------------- output

    /** The oldest queued output (Position, Stride or Step), or null when the queue is empty. */
    public Output poll() {
        lifetime.readLock().lock();
        try {
            synchronized (outputLock) {
                int type = nativePoll(live(), pollLongs, pollDoubles);
                switch (type) {
                    case 0:
                        return null;
                    case REC_POSITION:
                        return new Position(pollLongs, pollDoubles);
                    case REC_STRIDE:
                        return new Stride(pollLongs, pollDoubles);
                    case REC_STEP:
                        return new Step(pollLongs, pollDoubles);
                    default:
                        throw new IllegalStateException("unexpected record type " + type);
                }
            }
        } finally {
            lifetime.readLock().unlock();
        }
    }

    /** Every queued output, oldest first (empty when none). */
    public List<Output> pollAll() {
        List<Output> out = new ArrayList<>();
        for (Output o = poll(); o != null; o = poll()) out.add(o);
        return out;
    }

    /** Output latency of the pipeline in ns (the sum of the stages' look-ahead). */
    public long latencyNs() {
        lifetime.readLock().lock();
        try {
            return nativeLatencyNs(live());
        } finally {
            lifetime.readLock().unlock();
        }
    }

    /**
     * JSON description: engine version, loaded libraries and plugins, rejected
     * plugin files with reasons, the pipeline with its stages and latency, and
     * counters.
     */
    public String describe() {
        lifetime.readLock().lock();
        try {
            synchronized (inputLock) {
                return new String(nativeDescribe(live()), StandardCharsets.UTF_8);
            }
        } finally {
            lifetime.readLock().unlock();
        }
    }

    /** Whether {@link #close()} has been called. */
    public boolean isClosed() {
        lifetime.readLock().lock();
        try {
            return handle == 0;
        } finally {
            lifetime.readLock().unlock();
        }
    }

    /** Destroys the native engine; waits for calls in progress. Safe to call again. */
    @Override
    public void close() {
        lifetime.writeLock().lock();
        try {
            long h = handle;
            handle = 0;
            if (h != 0) nativeDestroy(h);
        } finally {
            lifetime.writeLock().unlock();
        }
    }

    private long live() {
        long h = handle;
        if (h == 0) throw new IllegalStateException("the engine is closed");
        return h;
    }

    // --------------------------------------------------------------- native

    private static native long nativeCreate(byte[] configUtf8, byte[][] pluginDirsUtf8);

    private static native void nativeDestroy(long handle);

    private static native void nativePushImu(long handle, long tNs, double ax, double ay, double az, double gx,
            double gy, double gz);

    private static native void nativePushImuBulk(long handle, long[] tNs, double[] accel, double[] gyro);

    private static native void nativePushMag(long handle, long tNs, double mx, double my, double mz);

    private static native void nativePushBaro(long handle, long tNs, double pressurePa, double temperatureC);

    private static native void nativePushGnss(long handle, long tNs, double latDeg, double lonDeg, double heightM,
            double hAccuracyM, double vAccuracyM, boolean hasVelocity, double ve, double vn, double vu, long utcNs);

    private static native void nativeFlush(long handle);

    private static native void nativeReset(long handle);

    private static native void nativeSetStart(long handle, double x, double y, double z, double headingDeg);

    private static native int nativePoll(long handle, long[] longs, double[] doubles);

    private static native long nativeLatencyNs(long handle);

    private static native byte[] nativeDescribe(long handle);

    private static native int nativeAbiVersion();

    private static native byte[] nativeVersion();
}
