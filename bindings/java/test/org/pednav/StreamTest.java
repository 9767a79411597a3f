// SPDX-License-Identifier: Apache-2.0
package org.pednav;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.pednav.TestSupport.config;
import static org.pednav.TestSupport.fixtureConfig;
import static org.pednav.TestSupport.fixtureDir;
import static org.pednav.TestSupport.ofType;
import static org.pednav.TestSupport.pushStill;
import static org.pednav.TestSupport.stage;
import static org.pednav.TestSupport.t;

import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A synthetic stream through the fixture plugins, with every output predicted
 * exactly from tests/fixtures/plugins/good_plugin.cpp: a STEP every 10 samples
 * (decided 3 samples late), heading 0 (due north), 0.5 m per step.
 */
class StreamTest {
    /** Asserts the Step, Stride, Position triple of step k (1-based) after a start at (x0, y0, z0). */
    private static void assertStepTriple(List<Output> out, int at, int k, double x0, double y0, double z0) {
        long tk = t(10 * k - 1); // the 10th, 20th, ... sample
        Step step = assertInstanceOf(Step.class, out.get(at));
        assertEquals(tk, step.tNs());
        assertEquals(tk - 10 * TestSupport.DT_NS, step.tStartNs());
        assertEquals(10.0, step.frequencyHz());
        assertEquals(0.0, step.accelPeakToPeakMps2());
        assertEquals(1, step.sourceId()); // stage 0

        Stride stride = assertInstanceOf(Stride.class, out.get(at + 1));
        assertEquals(tk, stride.tNs());
        assertEquals(k - 1, stride.index());
        assertEquals(tk - 10 * TestSupport.DT_NS, stride.tStartNs());
        assertArrayEquals(new double[] {0.0, 0.5, 0.0}, stride.displacementEnuM());
        assertEquals(0.5, stride.lengthM());
        assertEquals(Stride.CLASS_LEVEL, stride.strideClass());
        assertArrayEquals(new double[] {0.01, 0, 0, 0, 0.01, 0, 0, 0, 0}, stride.covDisplacementM2());

        Position p = assertInstanceOf(Position.class, out.get(at + 2));
        assertEquals(tk, p.tNs());
        assertEquals(3, p.sourceId()); // stage 2, the position filter
        assertArrayEquals(new double[] {x0, y0 + 0.5 * k, z0}, p.posEnuM());
        assertEquals(x0, p.east());
        assertEquals(y0 + 0.5 * k, p.north());
        assertEquals(z0, p.up());
        assertArrayEquals(new double[] {0.01 * k, 0, 0, 0, 0.01 * k, 0, 0, 0, 0.001 * k}, p.covEnuM2());
        assertEquals(0.01 * k, p.cov(1, 1));
        assertEquals(0.0, p.headingRad());
        assertFalse(p.hasFloor());
        assertFalse(p.hasVelocity());
        assertEquals(Position.SOURCE_INERTIAL, p.source());
    }

    @Test
    void exactPositionsStridesAndStepsWithLookAheadAndFlush() {
        try (Engine e = Engine.create(fixtureConfig(10, 3, 0.0, 0.5), fixtureDir("good"))) {
            e.setStart(10.0, 20.0, 1.5, Double.NaN);
            assertNull(e.poll());
            pushStill(e, 0, 100);
            // The step at the 100th sample is still inside the 3-sample look-ahead.
            List<Output> out = e.pollAll();
            assertEquals(9 * 3, out.size());
            for (int k = 1; k <= 9; ++k) assertStepTriple(out, 3 * (k - 1), k, 10.0, 20.0, 1.5);
            assertNull(e.poll());

            e.flush();
            out = e.pollAll();
            assertEquals(3, out.size());
            assertStepTriple(out, 0, 10, 10.0, 20.0, 1.5);
            assertEquals(25.0, ((Position) out.get(2)).north());
            assertNull(e.poll());
            assertEquals(100, TestSupport.counter(e, "records_in"));
        }
    }

    @Test
    void startHeadingTurnsTheWalkWithoutAnAttitudeStage() {
        // Without an attitude estimator the filter walks along the start heading: 90 deg = east.
        String cfg = config(stage("step_detector", "org.pednav.test.counting_steps", "\"every_n\": 10"),
                stage("position_filter", "org.pednav.test.step_counter", "\"step_length_m\": 0.5"));
        try (Engine e = Engine.create(cfg, fixtureDir("good"))) {
            e.setStart(0.0, 0.0, 0.0, 90.0);
            pushStill(e, 0, 40);
            e.flush(); // outputs about the last sample wait for a later sample or a flush
            List<Position> pos = ofType(e.pollAll(), Position.class);
            assertEquals(4, pos.size());
            for (int k = 1; k <= 4; ++k) {
                Position p = pos.get(k - 1);
                assertEquals(0.5 * k, p.east());
                assertEquals(0.0, p.north(), 1e-15 * k); // 0.5 cos(pi/2) per step
                assertEquals(Math.PI / 2, p.headingRad(), 1e-15);
            }
        }
    }

    @Test
    void resetStartsOverFromStepZero() {
        try (Engine e = Engine.create(fixtureConfig(10, 0, 0.0, 0.5), fixtureDir("good"))) {
            pushStill(e, 0, 35);
            assertEquals(3, ofType(e.pollAll(), Stride.class).size());
            pushStill(e, 35, 10); // queued, then dropped by reset
            e.reset();
            assertNull(e.poll());
            // Time may start again from the beginning after a reset. The 21st
            // sample releases the outputs about the 20th.
            pushStill(e, 0, 21);
            List<Output> out = e.pollAll();
            assertEquals(6, out.size());
            assertStepTriple(out, 0, 1, 0.0, 0.0, 0.0);
            assertStepTriple(out, 3, 2, 0.0, 0.0, 0.0);
        }
    }

    @Test
    void barometerSetsTheFloorThroughTheMapMatcher() {
        String cfg = config(stage("step_detector", "org.pednav.test.counting_steps", "\"every_n\": 10"),
                stage("position_filter", "org.pednav.test.step_counter", "\"step_length_m\": 0.5"),
                stage("map_matcher", "org.pednav.test.floor_from_baro", "\"floor_height_m\": 3.0"));
        try (Engine e = Engine.create(cfg, fixtureDir("good"))) {
            // Baro every 5th sample, at the IMU sample's time: 101325 Pa for
            // the first step, then 72 Pa less (2 floors of 3 m at 12 Pa/m).
            for (int i = 0; i < 30; ++i) {
                e.pushImu(t(i), 0.0, 0.0, 9.81, 0.0, 0.0, 0.0);
                if (i % 5 == 4) e.pushBaro(t(i), i < 10 ? 101325.0 : 101253.0, Double.NaN);
            }
            e.flush();
            List<Position> pos = ofType(e.pollAll(), Position.class);
            assertEquals(3, pos.size());
            int[] floors = {0, 2, 2};
            for (int k = 0; k < 3; ++k) {
                Position p = pos.get(k);
                assertTrue(p.hasFloor());
                assertEquals(floors[k], p.floor(), p.toString());
                assertEquals(Position.SOURCE_MAP, p.source());
                assertEquals(0.5 * (k + 1), p.north());
            }
            assertEquals(36, TestSupport.counter(e, "records_in"));
        }
    }

    @Test
    void magnetometerAndGnssSamplesAreAccepted() {
        try (Engine e = Engine.create(fixtureConfig(10, 0, 0.0, 0.5), fixtureDir("good"))) {
            for (int i = 0; i < 20; ++i) {
                e.pushImu(t(i), 0.0, 0.0, 9.81, 0.0, 0.0, 0.0);
                e.pushMag(t(i), 20.0, 0.0, -40.0);
            }
            e.pushGnss(t(19), 48.1, 11.5, 520.0, 3.0, 5.0);
            e.pushGnss(t(20), 48.1, 11.5, 520.0, 3.0, 5.0, new double[] {0.5, 1.0, 0.0}, 1_700_000_000_000_000_000L);
            assertEquals(42, TestSupport.counter(e, "records_in"));
            e.flush();
            assertEquals(2, ofType(e.pollAll(), Stride.class).size());
        }
    }

    @Test
    void valueClassesAreImmutableAndCompareByValue() {
        List<Output> a, b;
        try (Engine e = Engine.create(fixtureConfig(10, 0, 0.0, 0.5), fixtureDir("good"))) {
            pushStill(e, 0, 11);
            a = e.pollAll();
        }
        try (Engine e = Engine.create(fixtureConfig(10, 0, 0.0, 0.5), fixtureDir("good"))) {
            pushStill(e, 0, 11);
            b = e.pollAll();
        }
        assertEquals(a, b);
        assertEquals(a.hashCode(), b.hashCode());
        Position p = (Position) a.get(2);
        p.posEnuM()[1] = 99.0;
        p.covEnuM2()[0] = 99.0;
        assertEquals(0.5, p.north());
        assertEquals(0.01, p.cov(0, 0));
        assertEquals(b.get(2), p);
        assertTrue(p.toString().contains("pos_enu_m=[0.0, 0.5, 0.0]"), p.toString());
    }
}
