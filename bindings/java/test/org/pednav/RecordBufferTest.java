// SPDX-License-Identifier: Apache-2.0
package org.pednav;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.pednav.TestSupport.assertSameOutputs;
import static org.pednav.TestSupport.config;
import static org.pednav.TestSupport.fixtureConfig;
import static org.pednav.TestSupport.fixtureDir;
import static org.pednav.TestSupport.firstPartyPluginDir;
import static org.pednav.TestSupport.footConfig;
import static org.pednav.TestSupport.ofType;
import static org.pednav.TestSupport.stage;
import static org.pednav.TestSupport.t;

import java.nio.BufferOverflowException;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Direct ByteBuffer pushes (RecordBuffer, one JNI call per batch, read by the
 * engine in place) give the outputs of sample-by-sample pushes bit for bit,
 * for IMU-only and mixed batches of any size; batched polls give those of
 * poll() one at a time.
 */
class RecordBufferTest {
    private static final int[] BATCH_RECORDS = {1, 63, 64, 65, 2, 255, 256, 257, 7, 1000};

    private static List<Output> oneByOne(TestSupport.Stream s) {
        try (Engine e = Engine.create(footConfig(), firstPartyPluginDir())) {
            s.pushOneByOne(e);
            e.flush();
            return e.pollAll();
        }
    }

    private static List<Output> throughBuffers(TestSupport.Stream s) {
        try (Engine e = Engine.create(footConfig(), firstPartyPluginDir())) {
            RecordBuffer b = new RecordBuffer(1000 * RecordBuffer.IMU_RECORD_BYTES);
            int i = 0;
            for (int j = 0; i < s.size(); ++j) {
                b.clear();
                int m = Math.min(BATCH_RECORDS[j % BATCH_RECORDS.length], s.size() - i);
                for (int k = i; k < i + m; ++k)
                    b.putImu(s.tNs[k], s.accel[3 * k], s.accel[3 * k + 1], s.accel[3 * k + 2], s.gyro[3 * k],
                            s.gyro[3 * k + 1], s.gyro[3 * k + 2]);
                assertEquals(m, b.size());
                assertEquals(m * RecordBuffer.IMU_RECORD_BYTES, b.sizeBytes());
                e.push(b);
                i += m;
            }
            e.flush();
            return e.pollAll();
        }
    }

    @Test
    void imuBuffersThroughTheFootPipelineEqualPerSamplePushes() {
        TestSupport.Stream s = new TestSupport.Stream(12);
        List<Output> ref = oneByOne(s);
        assertTrue(ofType(ref, Stride.class).size() >= 10, "strides " + ofType(ref, Stride.class).size());
        assertSameOutputs(ref, throughBuffers(s));
        // The comparison sees a change of 1e-9 m/s^2 in one sample.
        s.accel[3 * 570] += 1e-9;
        assertTrue(TestSupport.firstDifference(ref, throughBuffers(s)) >= 0);
    }

    /** 30 IMU samples, a magnetometer sample each, a barometer every 5th (2 floors up after the first step). */
    private static RecordBuffer mixed(int from, int to) {
        RecordBuffer b = new RecordBuffer(30 * (RecordBuffer.IMU_RECORD_BYTES + RecordBuffer.MAG_RECORD_BYTES
                + RecordBuffer.BARO_RECORD_BYTES + RecordBuffer.GNSS_RECORD_BYTES));
        for (int i = from; i < to; ++i) {
            b.putImu(t(i), 0.0, 0.0, 9.81, 0.0, 0.0, 0.0);
            b.putMag(t(i), 20.0, 0.0, -40.0);
            if (i % 5 == 4) b.putBaro(t(i), i < 10 ? 101325.0 : 101253.0, Double.NaN);
            if (i == 15) b.putGnss(t(i), 48.1, 11.5, 520.0, 3.0, 5.0);
        }
        return b;
    }

    @Test
    void mixedBuffersEqualPerSamplePushes() {
        String cfg = config(stage("step_detector", "org.pednav.test.counting_steps", "\"every_n\": 10"),
                stage("position_filter", "org.pednav.test.step_counter", "\"step_length_m\": 0.5"),
                stage("map_matcher", "org.pednav.test.floor_from_baro", "\"floor_height_m\": 3.0"));
        List<Output> ref;
        try (Engine e = Engine.create(cfg, fixtureDir("good"))) {
            for (int i = 0; i < 30; ++i) {
                e.pushImu(t(i), 0.0, 0.0, 9.81, 0.0, 0.0, 0.0);
                e.pushMag(t(i), 20.0, 0.0, -40.0);
                if (i % 5 == 4) e.pushBaro(t(i), i < 10 ? 101325.0 : 101253.0, Double.NaN);
                if (i == 15) e.pushGnss(t(i), 48.1, 11.5, 520.0, 3.0, 5.0);
            }
            e.flush();
            ref = e.pollAll();
            assertEquals(67, TestSupport.counter(e, "records_in"));
        }
        try (Engine e = Engine.create(cfg, fixtureDir("good"))) {
            e.push(mixed(0, 13));
            e.push(mixed(13, 30));
            e.flush();
            List<Output> out = e.pollAll();
            assertSameOutputs(ref, out);
            assertEquals(67, TestSupport.counter(e, "records_in"));
            List<Position> pos = ofType(out, Position.class);
            assertEquals(3, pos.size());
            assertEquals(0, pos.get(0).floor()); // the barometer's values arrived: 72 Pa = 2 floors of 3 m
            assertEquals(2, pos.get(2).floor());
        }
    }

    @Test
    void aRejectedRecordStopsThePushAtItsIndex() {
        RecordBuffer b = mixed(0, 30);
        RecordBuffer bad = new RecordBuffer(400 * RecordBuffer.IMU_RECORD_BYTES);
        for (int i = 0; i < 300; ++i) bad.putImu(t(i), 0.0, 0.0, 9.81, 0.0, i == 270 ? Double.NaN : 0.0, 0.0);
        try (Engine e = Engine.create(fixtureConfig(10, 0, 0.0, 0.5), fixtureDir("good"))) {
            PednavException x = assertThrows(PednavException.class, () -> e.push(bad));
            assertEquals("PN_E_NUMERIC", x.statusName());
            assertEquals(270, x.detail());
            assertEquals(270, TestSupport.counter(e, "records_in"));
            // Steps at the 10th .. 260th sample; the 270th waits for a later sample.
            assertEquals(26, ofType(e.pollAll(), Position.class).size());
        }
        // Mixed buffer, past the glue's 256-pointer chunks: time going back in record 300.
        RecordBuffer late = new RecordBuffer(400 * RecordBuffer.MAG_RECORD_BYTES);
        for (int i = 0; i < 350; ++i) late.putMag(i == 300 ? t(0) : t(i + 1), 20.0, 0.0, -40.0);
        try (Engine e = Engine.create(fixtureConfig(10, 0, 0.0, 0.5), fixtureDir("good"))) {
            PednavException x = assertThrows(PednavException.class, () -> e.push(late));
            assertEquals("PN_E_OUT_OF_ORDER", x.statusName());
            assertEquals(300, x.detail());
            assertEquals(300, TestSupport.counter(e, "records_in"));
        }
        assertEquals(30 + 30 + 6 + 1, b.size());
    }

    @Test
    void aFullBufferThrowsAndKeepsItsRecords() {
        RecordBuffer b = new RecordBuffer(2 * RecordBuffer.IMU_RECORD_BYTES + 10);
        b.putImu(t(0), 0, 0, 9.81, 0, 0, 0).putImu(t(1), 0, 0, 9.81, 0, 0, 0);
        assertThrows(BufferOverflowException.class, () -> b.putImu(t(2), 0, 0, 9.81, 0, 0, 0));
        assertEquals(2, b.size());
        assertThrows(BufferOverflowException.class, () -> b.putMag(t(2), 0, 0, 0));
        b.clear();
        assertEquals(0, b.sizeBytes());
        assertThrows(IllegalArgumentException.class, () -> new RecordBuffer(-1));
    }

    @Test
    void batchedPollsEqualOneAtATime() {
        List<Output> single = new ArrayList<>(), batched = new ArrayList<>();
        for (int pass = 0; pass < 2; ++pass) {
            try (Engine e = Engine.create(fixtureConfig(10, 0, 0.0, 0.5), fixtureDir("good"))) {
                e.setOutputMask(Output.MASK_DEFAULT | Output.MASK_ATTITUDE | Output.MASK_GAIT_PHASE);
                TestSupport.pushStill(e, 0, 300);
                e.flush();
                if (pass == 0) {
                    for (Output o = e.poll(); o != null; o = e.poll()) single.add(o);
                } else {
                    batched.addAll(e.pollMany(10));
                    assertEquals(10, batched.size());
                    batched.addAll(e.pollMany(100)); // more than the 64 slots of one native call
                    assertEquals(110, batched.size());
                    batched.addAll(e.pollAll());
                    assertTrue(e.pollMany(5).isEmpty());
                }
            }
        }
        assertEquals(300 + 300 + 3 * 30, single.size());
        assertSameOutputs(single, batched);
    }
}
