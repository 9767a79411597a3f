// SPDX-License-Identifier: Apache-2.0
package org.pednav;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.pednav.TestSupport.config;
import static org.pednav.TestSupport.fixtureConfig;
import static org.pednav.TestSupport.fixtureDir;
import static org.pednav.TestSupport.ofType;
import static org.pednav.TestSupport.pushStill;
import static org.pednav.TestSupport.stage;
import static org.pednav.TestSupport.t;

import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;

/** Rejected input, plugin failures, misuse and closed engines: Java exceptions, never a crash. */
class ErrorTest {
    private static Engine fixtureEngine() {
        return Engine.create(fixtureConfig(10, 3, 0.0, 0.5), fixtureDir("good"));
    }

    @Test
    void nanSampleIsRejectedAndEarlierOutputsStayPollable() {
        try (Engine e = fixtureEngine()) {
            pushStill(e, 0, 50);
            PednavException x = assertThrows(PednavException.class,
                    () -> e.pushImu(t(50), 0.0, 0.0, 9.81, 0.0, Double.NaN, 0.0));
            assertEquals(PednavException.NUMERIC, x.status());
            assertEquals("PN_E_NUMERIC", x.statusName());
            assertEquals("input", x.where());
            assertEquals(0, x.detail());
            // Steps at samples 10..40 were decided (3-sample look-ahead) before the NaN.
            List<Output> out = e.pollAll();
            assertEquals(12, out.size());
            List<Position> pos = ofType(out, Position.class);
            assertEquals(4, pos.size());
            assertEquals(2.0, pos.get(3).north());
            assertEquals(t(39), pos.get(3).tNs());
            // The stream goes on after the rejected sample; the fifth step (the
            // 50th sample, i = 49) was still inside the look-ahead and now comes out.
            pushStill(e, 51, 9);
            assertEquals(59, TestSupport.counter(e, "records_in"));
            e.flush();
            pos = ofType(e.pollAll(), Position.class);
            assertEquals(1, pos.size());
            assertEquals(2.5, pos.get(0).north());
            assertEquals(t(49), pos.get(0).tNs());
        }
    }

    @Test
    void nanInBulkPushReportsItsIndexAcrossNativeChunks() {
        TestSupport.Stream s = new TestSupport.Stream(3);
        s.gyro[3 * 130 + 2] = Double.POSITIVE_INFINITY; // sample 130: past the first 64-sample chunks
        try (Engine e = fixtureEngine()) {
            PednavException x = assertThrows(PednavException.class, () -> e.pushImu(s.tNs, s.accel, s.gyro));
            assertEquals("PN_E_NUMERIC", x.statusName());
            assertEquals(130, x.detail());
            assertEquals(130, TestSupport.counter(e, "records_in"));
            // Samples 0..129 went in: steps at the 10th..120th sample are out.
            List<Position> pos = ofType(e.pollAll(), Position.class);
            assertEquals(12, pos.size());
            assertEquals(6.0, pos.get(11).north());
        }
    }

    @Test
    void timeGoingBackwardsIsOutOfOrder() {
        try (Engine e = fixtureEngine()) {
            pushStill(e, 0, 5);
            PednavException x = assertThrows(PednavException.class,
                    () -> e.pushImu(t(4), 0.0, 0.0, 9.81, 0.0, 0.0, 0.0));
            assertEquals("PN_E_OUT_OF_ORDER", x.statusName());
            assertEquals(PednavException.OUT_OF_ORDER, x.status());
            long[] ts = {t(5), t(6), t(6)};
            x = assertThrows(PednavException.class, () -> e.pushImu(ts, new double[9], new double[9]));
            assertEquals("PN_E_OUT_OF_ORDER", x.statusName());
            assertEquals(2, x.detail());
            x = assertThrows(PednavException.class, () -> e.pushBaro(t(3), 101325.0, 20.0));
            assertEquals("PN_E_OUT_OF_ORDER", x.statusName());
            assertEquals(7, TestSupport.counter(e, "records_in"));
        }
    }

    @Test
    void pluginExceptionBecomesInternalError() {
        String cfg = config(stage("step_detector", "org.pednav.test.throws", "\"throw_at\": 5"));
        try (Engine e = Engine.create(cfg, fixtureDir("throws"))) {
            pushStill(e, 0, 4);
            // Sample 5 (index 0 of this push) throws inside the plugin; the
            // engine reports it at the latest when the next sample goes in.
            TestSupport.Stream s = new TestSupport.Stream(0);
            PednavException x = assertThrows(PednavException.class, () -> s.pushBulk(e, 4, 10));
            assertTrue(x.detail() == 0 || x.detail() == 1, "detail " + x.detail());
            assertEquals(PednavException.INTERNAL, x.status());
            assertEquals("PN_E_INTERNAL", x.statusName());
            assertEquals("foot/step_detector", x.where());
            assertTrue(x.errorMessage().contains("fixture failure at sample 5"), x.errorMessage());
        }
    }

    @Test
    void badStartIsInvalidArgument() {
        try (Engine e = fixtureEngine()) {
            PednavException x = assertThrows(PednavException.class, () -> e.setStart(Double.NaN, 0.0, 0.0, 0.0));
            assertEquals("PN_E_INVALID_ARGUMENT", x.statusName());
            assertEquals("start", x.where());
        }
    }

    @Test
    void nullAndMismatchedArraysThrowAndLeaveTheEngineUsable() {
        try (Engine e = fixtureEngine()) {
            long[] t2 = {t(0), t(1)};
            double[] v6 = new double[6];
            assertThrows(NullPointerException.class, () -> e.pushImu(null, v6, v6));
            assertThrows(NullPointerException.class, () -> e.pushImu(t2, null, v6));
            assertThrows(NullPointerException.class, () -> e.pushImu(t2, v6, null));
            assertThrows(IllegalArgumentException.class, () -> e.pushImu(t2, new double[5], v6));
            assertThrows(IllegalArgumentException.class, () -> e.pushImu(t2, v6, new double[7]));
            assertThrows(IllegalArgumentException.class, () -> e.pushImu(new long[1], v6, v6));
            assertThrows(IllegalArgumentException.class,
                    () -> e.pushGnss(t(0), 48.0, 11.0, 500.0, 3.0, 5.0, new double[2], 0L));
            assertEquals(0, TestSupport.counter(e, "records_in"));
            e.pushImu(new long[0], new double[0], new double[0]); // empty is fine
            double[] accel = {0, 0, 9.81, 0, 0, 9.81};
            e.pushImu(t2, accel, v6);
            assertEquals(2, TestSupport.counter(e, "records_in"));
        }
    }

    @Test
    void closedEngineThrowsAndCloseTwiceIsSafe() {
        Engine e = fixtureEngine();
        pushStill(e, 0, 20);
        e.close();
        assertTrue(e.isClosed());
        assertDoesNotThrow(e::close);
        assertDoesNotThrow(e::close);
        double[] v3 = new double[3];
        assertThrows(IllegalStateException.class, () -> e.pushImu(t(20), 0, 0, 9.81, 0, 0, 0));
        assertThrows(IllegalStateException.class, () -> e.pushImu(new long[] {t(20)}, v3, v3));
        assertThrows(IllegalStateException.class, () -> e.pushMag(t(20), 1, 2, 3));
        assertThrows(IllegalStateException.class, () -> e.pushBaro(t(20), 101325.0, 20.0));
        assertThrows(IllegalStateException.class, () -> e.pushGnss(t(20), 48.0, 11.0, 500.0, 3.0, 5.0));
        assertThrows(IllegalStateException.class, e::flush);
        assertThrows(IllegalStateException.class, e::reset);
        assertThrows(IllegalStateException.class, () -> e.setStart(0, 0, 0, 0));
        assertThrows(IllegalStateException.class, e::poll);
        assertThrows(IllegalStateException.class, e::latencyNs);
        assertThrows(IllegalStateException.class, e::describe);
    }

    @Test
    void pushAndPollFromTwoThreadsThenCloseUnderThePoller() throws Exception {
        final int n = 5000;
        Engine e = fixtureEngine();
        AtomicInteger positions = new AtomicInteger();
        Thread poller = new Thread(() -> {
            try {
                while (true) {
                    Output o = e.poll();
                    if (o instanceof Position) positions.incrementAndGet();
                    if (o == null) Thread.yield();
                }
            } catch (IllegalStateException closed) {
                // the engine was closed under the poller: its way out
            }
        });
        poller.start();
        pushStill(e, 0, n);
        e.flush();
        long deadline = System.nanoTime() + 10_000_000_000L;
        while (positions.get() < n / 10 && System.nanoTime() < deadline) Thread.sleep(1);
        e.close();
        poller.join(10_000);
        assertFalse(poller.isAlive());
        assertEquals(n / 10, positions.get());
    }
}
