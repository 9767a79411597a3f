// SPDX-License-Identifier: Apache-2.0
package org.pednav;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.File;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/** Configs, synthetic streams and plugin folders shared by the binding tests. */
final class TestSupport {
    /** IMU period of every synthetic stream: 100 Hz, the fixtures' default sample_period_s. */
    static final long DT_NS = 10_000_000L;

    private TestSupport() {}

    /** Time of sample i (0-based); the stream starts at 1 s. */
    static long t(int i) {
        return 1_000_000_000L + i * DT_NS;
    }

    /** ${PEDNAV_TEST_PLUGIN_DIR}/<name>, checked to hold libpnp_<name>.so. */
    static String fixtureDir(String name) {
        String dir = System.getProperty("pednav.test." + name + "PluginDir");
        assertTrue(dir != null, "system property pednav.test." + name + "PluginDir is not set");
        assertTrue(new File(dir, "libpnp_" + name + ".so").isFile(), "fixture plugin missing in " + dir);
        return dir;
    }

    /** <build>/lib/pednav/plugins, checked to hold the foot plugins. */
    static String firstPartyPluginDir() {
        String dir = System.getProperty("pednav.test.pluginDir");
        assertTrue(dir != null, "system property pednav.test.pluginDir is not set");
        for (String name : new String[] {"foot_stance", "foot_strapdown", "foot_ekf"})
            assertTrue(new File(dir, "libpnp_" + name + ".so").isFile(), "libpnp_" + name + ".so missing in " + dir);
        return dir;
    }

    static String stage(String role, String plugin, String params) {
        return "\"" + role + "\": {\"plugin\": \"" + plugin + "\", \"params\": {" + params + "}}";
    }

    static String config(String... stages) {
        return "{\"format\": \"pednav-config/1\", \"mount\": \"foot\", \"pipelines\": {\"foot\": {"
                + String.join(", ", stages) + "}}}";
    }

    /**
     * The fixture pipeline: a STEP every {@code everyN} samples decided
     * {@code latencySamples} samples late, a level attitude at
     * {@code headingDeg}, and {@code stepLengthM} along it per step.
     */
    static String fixtureConfig(int everyN, int latencySamples, double headingDeg, double stepLengthM) {
        return config(
                stage("step_detector", "org.pednav.test.counting_steps",
                        "\"every_n\": " + everyN + ", \"latency_samples\": " + latencySamples),
                stage("attitude_estimator", "org.pednav.test.fixed_heading", "\"heading_deg\": " + headingDeg),
                stage("position_filter", "org.pednav.test.step_counter", "\"step_length_m\": " + stepLengthM));
    }

    /** The first-party foot pipeline with every parameter at its default. */
    static String footConfig() {
        return config(stage("step_detector", "org.pednav.foot.stance.shoe", ""),
                stage("attitude_estimator", "org.pednav.foot.strapdown", ""),
                stage("position_filter", "org.pednav.foot.ekf15", ""));
    }

    /** n samples of a level IMU at rest: gravity on +z (FLU), no rotation. */
    static void pushStill(Engine e, int from, int n) {
        for (int i = from; i < from + n; ++i) e.pushImu(t(i), 0.0, 0.0, 9.81, 0.0, 0.0, 0.0);
    }

    /**
     * A synthetic foot-mounted walk at 100 Hz: 2 s still, then strides of
     * 0.4 s stance and 0.6 s swing (forward acceleration and pitch rate as
     * full sine periods, so the foot stops again), with a small deterministic
     * wobble so every sample differs. Returns {tNs[n]} and fills accel/gyro.
     */
    static final class Stream {
        final long[] tNs;
        final double[] accel;
        final double[] gyro;

        Stream(int strides) {
            int still = 200, stance = 40, swing = 60;
            int n = still + strides * (stance + swing) + stance;
            tNs = new long[n];
            accel = new double[3 * n];
            gyro = new double[3 * n];
            for (int i = 0; i < n; ++i) {
                tNs[i] = t(i);
                double wobble = 1e-3 * Math.sin(0.37 * i);
                double ax = wobble, ay = -wobble, az = 9.81 + wobble;
                double gx = 0.5 * wobble, gy = 0.0, gz = -0.5 * wobble;
                int k = i - still;
                if (k >= 0 && k % (stance + swing) >= stance && k / (stance + swing) < strides) {
                    double phase = 2.0 * Math.PI * (k % (stance + swing) - stance) / swing;
                    ax += 8.0 * Math.sin(phase);
                    az += 3.0 * Math.sin(2.0 * phase);
                    gy += 4.0 * Math.sin(phase);
                    gz += 0.05;
                }
                accel[3 * i] = ax;
                accel[3 * i + 1] = ay;
                accel[3 * i + 2] = az;
                gyro[3 * i] = gx;
                gyro[3 * i + 1] = gy;
                gyro[3 * i + 2] = gz;
            }
        }

        int size() {
            return tNs.length;
        }

        /** Samples [from, to) in one bulk call. */
        void pushBulk(Engine e, int from, int to) {
            e.pushImu(Arrays.copyOfRange(tNs, from, to), Arrays.copyOfRange(accel, 3 * from, 3 * to),
                    Arrays.copyOfRange(gyro, 3 * from, 3 * to));
        }

        void pushOneByOne(Engine e) {
            for (int i = 0; i < size(); ++i)
                e.pushImu(tNs[i], accel[3 * i], accel[3 * i + 1], accel[3 * i + 2], gyro[3 * i], gyro[3 * i + 1],
                        gyro[3 * i + 2]);
        }
    }

    static <T extends Output> List<T> ofType(List<Output> out, Class<T> type) {
        List<T> r = new ArrayList<>();
        for (Output o : out)
            if (type.isInstance(o)) r.add(type.cast(o));
        return r;
    }

    /** Index of the first record where a and b differ (bit-exact), or -1 when they are equal. */
    static int firstDifference(List<Output> a, List<Output> b) {
        for (int i = 0; i < Math.min(a.size(), b.size()); ++i)
            if (!a.get(i).equals(b.get(i))) return i;
        return a.size() == b.size() ? -1 : Math.min(a.size(), b.size());
    }

    /** Bit-exact equality of two output lists, reporting only the first difference. */
    static void assertSameOutputs(List<Output> expected, List<Output> actual) {
        int i = firstDifference(expected, actual);
        if (i >= 0)
            fail("outputs differ at record " + i + " of " + expected.size() + " / " + actual.size() + ": expected "
                    + (i < expected.size() ? expected.get(i) : "none") + ", got "
                    + (i < actual.size() ? actual.get(i) : "none"));
    }

    /** An integer counter from describe()'s "counters" object. */
    static long counter(Engine e, String name) {
        Matcher m = Pattern.compile("\"" + name + "\"\\s*:\\s*(\\d+)").matcher(e.describe());
        assertTrue(m.find(), "describe() has no counter " + name + ": " + e.describe());
        return Long.parseLong(m.group(1));
    }
}
