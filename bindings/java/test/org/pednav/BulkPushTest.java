// SPDX-License-Identifier: Apache-2.0
package org.pednav;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.pednav.TestSupport.assertSameOutputs;
import static org.pednav.TestSupport.fixtureConfig;
import static org.pednav.TestSupport.fixtureDir;
import static org.pednav.TestSupport.firstPartyPluginDir;
import static org.pednav.TestSupport.footConfig;
import static org.pednav.TestSupport.ofType;

import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The bulk pushImu (one JNI call, native buffer with an explicit stride) gives
 * the same outputs, bit for bit, as pushing sample by sample, however the
 * stream is batched. The foot pipeline makes every output depend on the
 * sample values, so a mixed-up axis, stride or chunk boundary would show.
 */
class BulkPushTest {
    /** Batch sizes around the glue's 64-sample chunk. */
    private static final int[] BATCHES = {1, 63, 64, 65, 2, 127, 128, 129, 7, 300};

    private static List<Output> oneByOne(String cfg, String dir, TestSupport.Stream s) {
        try (Engine e = Engine.create(cfg, dir)) {
            s.pushOneByOne(e);
            e.flush();
            return e.pollAll();
        }
    }

    private static List<Output> bulk(String cfg, String dir, TestSupport.Stream s) {
        try (Engine e = Engine.create(cfg, dir)) {
            e.pushImu(s.tNs, s.accel, s.gyro);
            e.flush();
            return e.pollAll();
        }
    }

    private static List<Output> batched(String cfg, String dir, TestSupport.Stream s) {
        try (Engine e = Engine.create(cfg, dir)) {
            int i = 0;
            for (int j = 0; i < s.size(); ++j) {
                int m = Math.min(BATCHES[j % BATCHES.length], s.size() - i);
                s.pushBulk(e, i, i + m);
                i += m;
            }
            e.flush();
            return e.pollAll();
        }
    }

    @Test
    void fixturePipelineBulkEqualsPerSample() {
        TestSupport.Stream s = new TestSupport.Stream(10);
        String cfg = fixtureConfig(10, 3, 30.0, 0.7);
        List<Output> ref = oneByOne(cfg, fixtureDir("good"), s);
        // One step per 10 samples, each a Step, a Stride and a Position.
        assertEquals(3 * (s.size() / 10), ref.size());
        assertSameOutputs(ref, bulk(cfg, fixtureDir("good"), s));
        assertSameOutputs(ref, batched(cfg, fixtureDir("good"), s));
    }

    @Test
    void footPipelineBulkEqualsPerSampleBitForBit() {
        TestSupport.Stream s = new TestSupport.Stream(12);
        String cfg = footConfig();
        String dir = firstPartyPluginDir();
        List<Output> ref = oneByOne(cfg, dir, s);
        List<Position> pos = ofType(ref, Position.class);
        List<Stride> strides = ofType(ref, Stride.class);
        System.out.println("foot pipeline, " + s.size() + " samples: " + ref.size() + " outputs, " + pos.size()
                + " positions, " + strides.size() + " strides");
        assertTrue(ref.size() > 100 && !pos.isEmpty(), "too few outputs from the synthetic walk: " + ref.size());

        assertSameOutputs(ref, bulk(cfg, dir, s));
        assertSameOutputs(ref, batched(cfg, dir, s));
    }

    @Test
    void footPipelineSeesASmallChangeInOneSample() {
        // Control for the equality above: the comparison is fine enough to
        // catch a single accelerometer value changed by 1e-9 m/s^2.
        TestSupport.Stream s = new TestSupport.Stream(12);
        String cfg = footConfig();
        String dir = firstPartyPluginDir();
        List<Output> ref = bulk(cfg, dir, s);
        int i = 200 + 3 * 100 + 70; // mid-swing of the fourth stride
        s.accel[3 * i] += 1e-9;
        List<Output> changed = bulk(cfg, dir, s);
        assertEquals(ref.size(), changed.size());
        assertTrue(TestSupport.firstDifference(ref, changed) >= 0, "a changed sample changed no output");
    }
}
