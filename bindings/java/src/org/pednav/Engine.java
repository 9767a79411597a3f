// SPDX-License-Identifier: Apache-2.0
package org.pednav;

import java.lang.ref.Cleaner;
import java.lang.ref.Reference;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
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
 * engine (try-with-resources) to free its native memory at once; an engine
 * that becomes unreachable without {@link #close()} is freed by a
 * {@link Cleaner} after the garbage collector finds it. {@link #close()} may
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
        RecordLayout.verify(nativeLayout());
    }

    /** Frees the native engines that were never closed. */
    private static final Cleaner CLEANER = Cleaner.create();
    /** pn_output_t slots per nativePollMany call. */
    private static final int POLL_SLOTS = 64;

    /** pnj_engine_t*, 0 once closed. Written only under the write lock. */
    private long handle;
    private final Cleaner.Cleanable cleanable;
    /** Kept here so that the glue's weak reference to it lives as long as the engine. */
    private final LogSink logSink;
    /** Read-held by every call, write-held by close: no call runs on a freed engine. */
    private final ReentrantReadWriteLock lifetime = new ReentrantReadWriteLock();
    /** Serialises the producer side (push, flush, reset, settings, describe). */
    private final Object inputLock = new Object();
    /** Serialises the consumer side (poll) and guards the poll buffer. */
    private final Object outputLock = new Object();
    /** POLL_SLOTS pn_output_t slots, allocated at the first poll. */
    private ByteBuffer pollBuffer;

    /** The Cleaner's action: holds the handle, never the Engine. */
    private static final class Destroy implements Runnable {
        private final long handle;

        Destroy(long handle) {
            this.handle = handle;
        }

        @Override
        public void run() {
            nativeDestroy(handle);
        }
    }

    private Engine(long handle, LogSink logSink) {
        this.handle = handle;
        this.logSink = logSink;
        this.cleanable = CLEANER.register(this, new Destroy(handle));
    }

    /**
     * Loads the plugins the config names from {@code pluginDirs} (searched in
     * order for libpnp_*.so) and builds the pipeline of the configured mount.
     *
     * @throws PednavException with {@link PednavException#where()} naming the
     *     config key (a JSON pointer) or the plugin file at fault
     */
    public static Engine create(String configJson, String... pluginDirs) {
        return create(configJson, null, pluginDirs);
    }

    /**
     * As {@link #create(String, String...)}, with every line the engine and
     * its plugins log, from the plugins' initialisation on, given to
     * {@code log} (null: no listener). See {@link LogListener} for its threads.
     */
    public static Engine create(String configJson, LogListener log, String... pluginDirs) {
        Objects.requireNonNull(configJson, "configJson");
        byte[][] dirs = new byte[pluginDirs == null ? 0 : pluginDirs.length][];
        for (int i = 0; i < dirs.length; ++i)
            dirs[i] = Objects.requireNonNull(pluginDirs[i], "pluginDirs[" + i + "]").getBytes(StandardCharsets.UTF_8);
        LogSink sink = log == null ? null : new LogSink(log);
        long h = nativeCreate(configJson.getBytes(StandardCharsets.UTF_8), dirs, sink);
        if (h == 0) throw new IllegalStateException("pn_engine_create returned no engine and no error");
        return new Engine(h, sink);
    }

    /** The engine library's ABI version: major in the high 16 bits, minor in the low 16. */
    public static int abiVersion() {
        return nativeAbiVersion();
    }

    /** The engine library's version, e.g. "0.1.0". */
    public static String version() {
        return new String(nativeVersion(), StandardCharsets.UTF_8);
    }

    /** Native engines created and not yet destroyed, in this process (for the binding's tests). */
    static long liveNativeEngines() {
        return nativeLiveEngines();
    }

    // ---------------------------------------------------------------- input

    /** One IMU sample: specific force (m/s^2) and angular rate (rad/s), body frame (FLU). */
    public void pushImu(long tNs, double axMps2, double ayMps2, double azMps2, double gxRadps, double gyRadps,
            double gzRadps) {
        lifetime.readLock().lock();
        try {
            synchronized (inputLock) {
                nativePushImu(live(), tNs, axMps2, ayMps2, azMps2, gxRadps, gyRadps, gzRadps);
            }
        } finally {
            lifetime.readLock().unlock();
            Reference.reachabilityFence(this);
        }
    }

    /**
     * n IMU samples in one native call: {@code tNs[n]}, {@code accelMps2[3n]}
     * and {@code gyroRadps[3n]} as x, y, z per sample. A rejected sample stops
     * the push there with a PednavException whose
     * {@link PednavException#detail()} is its index; the samples before it are
     * processed and kept.
     */
    public void pushImu(long[] tNs, double[] accelMps2, double[] gyroRadps) {
        Objects.requireNonNull(tNs, "tNs");
        Objects.requireNonNull(accelMps2, "accelMps2");
        Objects.requireNonNull(gyroRadps, "gyroRadps");
        if (accelMps2.length != 3L * tNs.length || gyroRadps.length != 3L * tNs.length)
            throw new IllegalArgumentException("accel and gyro must hold 3 values per time stamp: tNs.length="
                    + tNs.length + ", accel.length=" + accelMps2.length + ", gyro.length=" + gyroRadps.length);
        runProducer(h -> nativePushImuBulk(h, tNs, accelMps2, gyroRadps));
    }

    /**
     * Every record of {@code records} in one native call, read by the engine
     * in place (no copy): IMU samples, magnetometer, barometer and GNSS in the
     * order they were put. A rejected record stops the push there with a
     * PednavException whose {@link PednavException#detail()} is its index in
     * the buffer; the records before it are processed and kept. The buffer is
     * left as it is ({@link RecordBuffer#clear()} it to reuse it).
     */
    public void push(RecordBuffer records) {
        Objects.requireNonNull(records, "records");
        if (records.size() == 0) return;
        runProducer(h -> nativePushBuffer(h, records.buffer(), records.sizeBytes(), records.size(), records.imuOnly()));
    }

    /** One magnetometer sample in microtesla, body frame. */
    public void pushMag(long tNs, double mxUt, double myUt, double mzUt) {
        runProducer(h -> nativePushMag(h, tNs, mxUt, myUt, mzUt));
    }

    /** One barometer sample: static pressure (Pa) and temperature (deg C, NaN when unknown). */
    public void pushBaro(long tNs, double pressurePa, double temperatureC) {
        runProducer(h -> nativePushBaro(h, tNs, pressurePa, temperatureC));
    }

    /** One satellite fix (WGS-84, ellipsoidal height, 1-sigma accuracies in m) without velocity or UTC. */
    public void pushGnss(long tNs, double latDeg, double lonDeg, double heightM, double hAccuracyM,
            double vAccuracyM) {
        pushGnss(tNs, latDeg, lonDeg, heightM, hAccuracyM, vAccuracyM, null, 0L);
    }

    /**
     * One satellite fix (WGS-84). {@code velEnuMps} is null or 3 values
     * (east, north, up in m/s); {@code utcNs} is 0 when unknown. A fix may
     * give the engine its geodetic origin (see {@link #setOrigin}).
     */
    public void pushGnss(long tNs, double latDeg, double lonDeg, double heightM, double hAccuracyM,
            double vAccuracyM, double[] velEnuMps, long utcNs) {
        if (velEnuMps != null && velEnuMps.length != 3)
            throw new IllegalArgumentException("velEnuMps must hold 3 values, not " + velEnuMps.length);
        boolean hasVel = velEnuMps != null;
        double ve = hasVel ? velEnuMps[0] : 0.0, vn = hasVel ? velEnuMps[1] : 0.0, vu = hasVel ? velEnuMps[2] : 0.0;
        runProducer(h -> nativePushGnss(h, tNs, latDeg, lonDeg, heightM, hAccuracyM, vAccuracyM, hasVel, ve, vn, vu,
                utcNs));
    }

    // -------------------------------------------------------------- control

    /** End of stream: drains every stage's look-ahead. Pushing afterwards starts a new segment. */
    public void flush() {
        runProducer(Engine::nativeFlush);
    }

    /**
     * Back to the state right after create: plugins reset, queued outputs
     * dropped. The start, attitude, origin and map set before the first push
     * are given again to the fresh plugins; an origin taken from a GNSS fix is
     * forgotten.
     */
    public void reset() {
        runProducer(h -> {
            synchronized (outputLock) {
                nativeReset(h);
            }
        });
    }

    /**
     * Start point (ENU metres) and heading (degrees clockwise from north; NaN =
     * from the sensors) for the position filter and map matcher. Only before
     * the first push (or after a reset).
     */
    public void setStart(double eastM, double northM, double upM, double headingDeg) {
        runProducer(h -> nativeSetStart(h, eastM, northM, upM, headingDeg));
    }

    /**
     * Initial attitude for the attitude estimator instead of its own
     * alignment: a unit quaternion (Hamilton, w first) rotating body (FLU)
     * vectors into ENU. Only before the first push (or after a reset).
     *
     * @throws PednavException {@code PN_E_UNSUPPORTED} when the attitude
     *     estimator takes none, {@code PN_E_INVALID_ARGUMENT} when q is not a
     *     finite unit quaternion, {@code PN_E_BAD_STATE} after the first push
     */
    public void setAttitude(double qw, double qx, double qy, double qz) {
        runProducer(h -> nativeSetAttitude(h, qw, qx, qy, qz));
    }

    /**
     * The geodetic origin: the WGS-84 point at ENU (0, 0, 0), read by every
     * plugin and used by {@link #geoFromEnu} and {@link #enuFromGeo}. Only
     * before the first push and while the engine has no origin from its
     * config or map ({@code PN_E_BAD_STATE} naming where the current one came
     * from).
     */
    public void setOrigin(GeoPoint origin) {
        Objects.requireNonNull(origin, "origin");
        runProducer(h -> nativeSetOrigin(h, origin.latDeg(), origin.lonDeg(), origin.heightM()));
    }

    /**
     * The current geodetic origin (set by the app, the config, a map, or the
     * first good GNSS fix), or null while there is none.
     */
    public GeoPoint getOrigin() {
        double[] v = new double[3];
        return callProducer(h -> nativeGetOrigin(h, v)) ? new GeoPoint(v[0], v[1], v[2]) : null;
    }

    /** ENU metres to WGS-84 through the origin (exact, ellipsoidal), or null while there is no origin. */
    public GeoPoint geoFromEnu(double eastM, double northM, double upM) {
        double[] v = new double[3];
        return callProducer(h -> nativeGeoFromEnu(h, eastM, northM, upM, v)) ? new GeoPoint(v[0], v[1], v[2]) : null;
    }

    /** WGS-84 to ENU metres {east, north, up} through the origin, or null while there is no origin. */
    public double[] enuFromGeo(GeoPoint point) {
        Objects.requireNonNull(point, "point");
        double[] v = new double[3];
        return callProducer(h -> nativeEnuFromGeo(h, point.latDeg(), point.lonDeg(), point.heightM(), v)) ? v : null;
    }

    /**
     * Hands a map to the pipeline's map matcher, replacing the previous one,
     * from the next record on. {@code format} is "pednav.map/1" (GeoJSON,
     * docs/maps.md) or what the map matcher documents.
     *
     * @throws PednavException {@code PN_E_UNSUPPORTED} without a map matcher
     *     that takes maps; a refused map with {@link PednavException#where()}
     *     = "map:" + a JSON pointer to the feature at fault (the previous map
     *     stays)
     */
    public void loadMap(String format, byte[] mapBytes) {
        Objects.requireNonNull(format, "format");
        Objects.requireNonNull(mapBytes, "mapBytes");
        runProducer(h -> nativeLoadMap(h, format.getBytes(StandardCharsets.UTF_8), mapBytes));
    }

    /**
     * New params for one stage, named by role ("position_filter") or instance
     * ("foot/position_filter"): the whole "params" object as JSON, checked
     * like the config; applies from the next record and survives reset.
     *
     * @throws PednavException {@code PN_E_INVALID_CONFIG} with
     *     {@link PednavException#where()} a pointer relative to the stage
     *     ("/params/every_n"), {@code PN_E_NOT_FOUND} for a stage the
     *     pipeline lacks, {@code PN_E_UNSUPPORTED} when the plugin cannot
     *     change them live (the old values stay)
     */
    public void reconfigure(String stage, String paramsJson) {
        Objects.requireNonNull(stage, "stage");
        Objects.requireNonNull(paramsJson, "paramsJson");
        runProducer(h -> nativeReconfigure(h, stage.getBytes(StandardCharsets.UTF_8),
                paramsJson.getBytes(StandardCharsets.UTF_8)));
    }

    /**
     * Which record types reach the output queue, as {@code Output.MASK_*}
     * bits ({@link Output#MASK_DEFAULT} after create). Applies to records
     * emitted after the call; may be called from any thread.
     *
     * @throws PednavException {@code PN_E_INVALID_ARGUMENT} for any other
     *     bit; the mask stays as it was
     */
    public void setOutputMask(long mask) {
        lifetime.readLock().lock();
        try {
            nativeSetOutputMask(live(), mask);
        } finally {
            lifetime.readLock().unlock();
            Reference.reachabilityFence(this);
        }
    }

    // --------------------------------------------------------------- output

    /** The oldest queued output, or null when the queue is empty. */
    public Output poll() {
        List<Output> one = pollMany(1);
        return one.isEmpty() ? null : one.get(0);
    }

    /**
     * Up to {@code maxRecords} queued outputs, oldest first, taken from the
     * engine up to 64 at a time per native call (empty when none).
     */
    public List<Output> pollMany(int maxRecords) {
        if (maxRecords < 0) throw new IllegalArgumentException("maxRecords must not be negative: " + maxRecords);
        List<Output> out = new ArrayList<>();
        lifetime.readLock().lock();
        try {
            synchronized (outputLock) {
                if (pollBuffer == null)
                    pollBuffer = ByteBuffer.allocateDirect(POLL_SLOTS * RecordLayout.SLOT_BYTES + 8).alignedSlice(8)
                            .order(ByteOrder.nativeOrder());
                while (out.size() < maxRecords) {
                    int want = Math.min(POLL_SLOTS, maxRecords - out.size());
                    int n = nativePollMany(live(), pollBuffer, want);
                    for (int i = 0; i < n; ++i) {
                        Output o = new RecordLayout.Slot(pollBuffer, i * RecordLayout.SLOT_BYTES).decode();
                        if (o != null) out.add(o); // a type newer than this binding: skipped
                    }
                    if (n < want) break; // the queue is empty
                }
            }
        } finally {
            lifetime.readLock().unlock();
            Reference.reachabilityFence(this);
        }
        return out;
    }

    /** Every queued output, oldest first (empty when none). */
    public List<Output> pollAll() {
        return pollMany(Integer.MAX_VALUE);
    }

    /** Output latency of the pipeline in ns (the sum of the stages' look-ahead). */
    public long latencyNs() {
        return callProducer(Engine::nativeLatencyNs);
    }

    /**
     * JSON description: engine version, loaded libraries and plugins, rejected
     * plugin files with reasons, the pipeline with its stages and latency, the
     * origin and map, counters and warnings.
     */
    public String describe() {
        return new String(callProducer(Engine::nativeDescribe), StandardCharsets.UTF_8);
    }

    /** Exceptions the {@link LogListener} threw, caught by the binding (0 without a listener). */
    public long logListenerFailures() {
        return logSink == null ? 0 : logSink.failures();
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

    /**
     * Destroys the native engine now (its plugins' last log lines reach the
     * listener on this thread); waits for calls in progress. Safe to call again.
     */
    @Override
    public void close() {
        lifetime.writeLock().lock();
        try {
            if (handle != 0) {
                handle = 0;
                cleanable.clean(); // runs Destroy here, once; the Cleaner will not
            }
        } finally {
            lifetime.writeLock().unlock();
            Reference.reachabilityFence(this);
        }
    }

    private long live() {
        long h = handle;
        if (h == 0) throw new IllegalStateException("the engine is closed");
        return h;
    }

    private interface Call<T> {
        T on(long handle);
    }

    private interface VoidCall {
        void on(long handle);
    }

    /** Runs a producer-side native call on the live handle, keeping the engine reachable until it returns. */
    private <T> T callProducer(Call<T> call) {
        lifetime.readLock().lock();
        try {
            synchronized (inputLock) {
                return call.on(live());
            }
        } finally {
            lifetime.readLock().unlock();
            Reference.reachabilityFence(this);
        }
    }

    private void runProducer(VoidCall call) {
        callProducer(h -> {
            call.on(h);
            return null;
        });
    }

    // --------------------------------------------------------------- native

    private static native long nativeCreate(byte[] configUtf8, byte[][] pluginDirsUtf8, LogSink logSink);

    private static native void nativeDestroy(long handle);

    private static native long nativeLiveEngines();

    private static native int[] nativeLayout();

    private static native void nativePushImu(long handle, long tNs, double ax, double ay, double az, double gx,
            double gy, double gz);

    private static native void nativePushImuBulk(long handle, long[] tNs, double[] accel, double[] gyro);

    private static native void nativePushBuffer(long handle, ByteBuffer records, int bytes, int count,
            boolean imuOnly);

    private static native void nativePushMag(long handle, long tNs, double mx, double my, double mz);

    private static native void nativePushBaro(long handle, long tNs, double pressurePa, double temperatureC);

    private static native void nativePushGnss(long handle, long tNs, double latDeg, double lonDeg, double heightM,
            double hAccuracyM, double vAccuracyM, boolean hasVelocity, double ve, double vn, double vu, long utcNs);

    private static native void nativeFlush(long handle);

    private static native void nativeReset(long handle);

    private static native void nativeSetStart(long handle, double x, double y, double z, double headingDeg);

    private static native void nativeSetAttitude(long handle, double qw, double qx, double qy, double qz);

    private static native void nativeSetOrigin(long handle, double latDeg, double lonDeg, double heightM);

    private static native boolean nativeGetOrigin(long handle, double[] out);

    private static native boolean nativeGeoFromEnu(long handle, double east, double north, double up, double[] out);

    private static native boolean nativeEnuFromGeo(long handle, double latDeg, double lonDeg, double heightM,
            double[] out);

    private static native void nativeLoadMap(long handle, byte[] formatUtf8, byte[] mapBytes);

    private static native void nativeReconfigure(long handle, byte[] stageUtf8, byte[] paramsUtf8);

    private static native void nativeSetOutputMask(long handle, long mask);

    private static native int nativePollMany(long handle, ByteBuffer slots, int capacity);

    private static native long nativeLatencyNs(long handle);

    private static native byte[] nativeDescribe(long handle);

    private static native int nativeAbiVersion();

    private static native byte[] nativeVersion();
}
