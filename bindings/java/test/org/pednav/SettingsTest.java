// SPDX-License-Identifier: Apache-2.0
package org.pednav;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.pednav.TestSupport.config;
import static org.pednav.TestSupport.fixtureConfig;
import static org.pednav.TestSupport.fixtureDir;
import static org.pednav.TestSupport.ofType;
import static org.pednav.TestSupport.pushStill;
import static org.pednav.TestSupport.stage;
import static org.pednav.TestSupport.t;

import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The 1.1 settings through the fixture plugins: output mask, map and origin
 * (org.pednav.test.map_anchor moves every position to the map's first Point
 * in ENU around the origin and reports the number of features as the floor),
 * initial attitude, live reconfiguration.
 */
class SettingsTest {
    /** Origin 48.1 N 11.5 E 500 m; 1 deg of latitude is 111 200.994 m there (WGS-84 meridian radius, 500 m up). */
    private static final GeoPoint ORIGIN = new GeoPoint(48.1, 11.5, 500.0);
    private static final double NORTH_10M_DEG = 10.0 / 111200.994;

    private static String mapConfig() {
        return config(stage("step_detector", "org.pednav.test.counting_steps", ""),
                stage("position_filter", "org.pednav.test.step_counter", ""),
                stage("map_matcher", "org.pednav.test.map_anchor", ""));
    }

    private static byte[] mapWithPoint(double latDeg, String extra) {
        return ("{\"type\": \"FeatureCollection\"" + extra + ", \"features\": ["
                + "{\"type\": \"Feature\", \"geometry\": {\"type\": \"Point\", \"coordinates\": [11.5, " + latDeg
                + ", 501.5]}},"
                + "{\"type\": \"Feature\", \"geometry\": {\"type\": \"LineString\", \"coordinates\": [[11.5, 48.1], [11.5001, 48.1]]}}]}")
                .getBytes(StandardCharsets.UTF_8);
    }

    @Test
    void outputMaskChoosesWhatIsPolledAndChangesNoPosition() {
        String cfg = fixtureConfig(10, 0, 0.0, 0.5).replace("\"step_length_m\": 0.5",
                "\"step_length_m\": 0.5, \"correction_rad\": 0.25");
        List<Output> all, positionsOnly;
        try (Engine e = Engine.create(cfg, fixtureDir("good"))) {
            e.setOutputMask(Output.MASK_DEFAULT | Output.MASK_ATTITUDE | Output.MASK_GAIT_PHASE
                    | Output.MASK_ATTITUDE_CORRECTION);
            pushStill(e, 0, 20);
            e.flush();
            all = e.pollAll();
        }
        assertEquals(20, ofType(all, Attitude.class).size()); // one per IMU sample
        assertEquals(20, ofType(all, GaitPhase.class).size());
        assertEquals(2, ofType(all, Step.class).size());
        assertEquals(2, ofType(all, Stride.class).size());
        assertEquals(2, ofType(all, Position.class).size());
        List<AttitudeCorrection> corrections = ofType(all, AttitudeCorrection.class);
        assertEquals(2, corrections.size()); // one per step
        assertArrayEquals(new double[] {0.0, 0.0, 0.25}, corrections.get(0).rotationEnuRad());
        assertEquals(t(9), corrections.get(0).tNs());

        // Heading 0 (north): a level body yawed 90 deg from east, q = (cos 45, 0, 0, sin 45).
        Attitude a = ofType(all, Attitude.class).get(0);
        assertEquals(t(0), a.tNs());
        double[] q = a.qEnuFromBody();
        assertEquals(Math.sqrt(0.5), q[0], 1e-15);
        assertEquals(0.0, q[1]);
        assertEquals(0.0, q[2]);
        assertEquals(Math.sqrt(0.5), q[3], 1e-15);
        assertEquals(0.0, a.headingRad());
        // counting_steps: stance = (n / every_n) % 2 for the n-th sample (1-based).
        List<GaitPhase> phases = ofType(all, GaitPhase.class);
        for (int i = 0; i < 20; ++i) assertEquals(((i + 1) / 10) % 2 == 1, phases.get(i).stance(), "sample " + i);

        try (Engine e = Engine.create(cfg, fixtureDir("good"))) {
            e.setOutputMask(Output.MASK_POSITION);
            pushStill(e, 0, 20);
            e.flush();
            positionsOnly = e.pollAll();
            // A bit of an input type is refused, naming the mask, and the mask stays.
            PednavException x = assertThrows(PednavException.class,
                    () -> e.setOutputMask(Output.MASK_POSITION | (1L << 1)));
            assertEquals(PednavException.INVALID_ARGUMENT, x.status());
            assertEquals("output_mask", x.where());
            pushStill(e, 20, 11);
            assertEquals(1, e.pollAll().size());
        }
        assertEquals(2, positionsOnly.size());
        TestSupport.assertSameOutputs(ofType(all, Position.class).stream().map(p -> (Output) p).toList(), positionsOnly);
    }

    @Test
    void originAndMapRoundTrip() {
        try (Engine e = Engine.create(mapConfig(), fixtureDir("good"), fixtureDir("map_anchor"))) {
            assertNull(e.getOrigin());
            assertNull(e.geoFromEnu(0.0, 10.0, 1.5));
            assertNull(e.enuFromGeo(ORIGIN));
            e.setOrigin(ORIGIN);
            assertEquals(ORIGIN, e.getOrigin());
            e.loadMap("pednav.map/1", mapWithPoint(48.1 + NORTH_10M_DEG, ""));

            // A broken map: refused, naming the feature at fault; the good one stays.
            byte[] broken = ("{\"type\": \"FeatureCollection\", \"features\": ["
                    + "{\"type\": \"Feature\", \"geometry\": {\"type\": \"Point\", \"coordinates\": [11.5, 48.1]}},"
                    + "{\"type\": \"Feature\", \"geometry\": {\"type\": \"LineString\", \"coordinates\": [[11.5, 48.1], [11.5, \"x\"]]}}]}")
                    .getBytes(StandardCharsets.UTF_8);
            PednavException x = assertThrows(PednavException.class, () -> e.loadMap("pednav.map/1", broken));
            assertEquals(PednavException.BAD_INPUT, x.status());
            assertEquals("map:/features/1/geometry/coordinates/1", x.where());
            assertTrue(x.errorMessage().contains("a coordinate must be a number"), x.errorMessage());

            pushStill(e, 0, 50);
            e.flush();
            List<Position> pos = ofType(e.pollAll(), Position.class);
            assertEquals(5, pos.size()); // a step every 10 samples
            Position last = pos.get(4);
            assertEquals(0.0, last.east(), 1e-6);
            assertEquals(10.0, last.north(), 0.01);
            assertEquals(1.5, last.up(), 1e-4); // 1.5 m up, less the curvature over 10 m (8 um)
            assertTrue(last.hasFloor());
            assertEquals(2, last.floor()); // the map's two features

            // ENU -> WGS-84 -> ENU through the origin.
            GeoPoint g = e.geoFromEnu(0.0, 10.0, 1.5);
            assertEquals(48.1 + NORTH_10M_DEG, g.latDeg(), 1e-8);
            assertEquals(11.5, g.lonDeg(), 1e-12);
            assertEquals(501.5, g.heightM(), 1e-5);
            double[] back = e.enuFromGeo(g);
            assertArrayEquals(new double[] {0.0, 10.0, 1.5}, back, 1e-9);
            double[] atOrigin = e.enuFromGeo(ORIGIN);
            assertArrayEquals(new double[] {0.0, 0.0, 0.0}, atOrigin, 1e-9);

            x = assertThrows(PednavException.class, () -> e.setOrigin(ORIGIN));
            assertEquals(PednavException.BAD_STATE, x.status());
            e.reset(); // keeps the app's origin and map
            assertEquals(ORIGIN, e.getOrigin());
            pushStill(e, 0, 20);
            e.flush();
            pos = ofType(e.pollAll(), Position.class);
            assertEquals(2, pos.size());
            assertEquals(10.0, pos.get(1).north(), 0.01);
        }
        // Without an origin from the app, the map's own is taken.
        try (Engine e = Engine.create(mapConfig(), fixtureDir("good"), fixtureDir("map_anchor"))) {
            e.loadMap("pednav.map/1", mapWithPoint(48.2, ", \"pednav:origin\": [11.5, 48.2, 480.0]"));
            assertEquals(new GeoPoint(48.2, 11.5, 480.0), e.getOrigin());
            PednavException x = assertThrows(PednavException.class, () -> e.setOrigin(ORIGIN));
            assertTrue(x.errorMessage().contains("from a plugin (foot/map_matcher)"), x.errorMessage());
        }
        // A pipeline without a map matcher takes no map.
        try (Engine e = Engine.create(fixtureConfig(10, 0, 0.0, 0.5), fixtureDir("good"))) {
            PednavException x = assertThrows(PednavException.class,
                    () -> e.loadMap("pednav.map/1", mapWithPoint(48.1, "")));
            assertEquals(PednavException.UNSUPPORTED, x.status());
        }
    }

    @Test
    void initialAttitudeTurnsTheWalk() {
        try (Engine e = Engine.create(fixtureConfig(10, 0, 0.0, 0.5), fixtureDir("good"))) {
            PednavException x = assertThrows(PednavException.class, () -> e.setAttitude(2.0, 0.0, 0.0, 0.0));
            assertEquals(PednavException.INVALID_ARGUMENT, x.status());
            // Identity: body x along east, heading 90 deg: the walk goes east.
            e.setAttitude(1.0, 0.0, 0.0, 0.0);
            pushStill(e, 0, 20);
            e.flush();
            List<Position> pos = ofType(e.pollAll(), Position.class);
            assertEquals(2, pos.size());
            assertEquals(1.0, pos.get(1).east(), 1e-15);
            assertEquals(0.0, pos.get(1).north(), 1e-15);
            assertEquals(Math.PI / 2, pos.get(1).headingRad(), 1e-15);
            x = assertThrows(PednavException.class, () -> e.setAttitude(1.0, 0.0, 0.0, 0.0));
            assertEquals(PednavException.BAD_STATE, x.status());
        }
    }

    @Test
    void reconfigureChangesTheStepDetectorLive() {
        try (Engine e = Engine.create(fixtureConfig(10, 0, 0.0, 0.5), fixtureDir("good"))) {
            pushStill(e, 0, 20);
            e.reconfigure("step_detector", "{\"every_n\": 5}");
            pushStill(e, 20, 20);
            e.flush();
            List<Stride> strides = ofType(e.pollAll(), Stride.class);
            // Samples 10, 20, then every 5th: 25, 30, 35, 40.
            assertEquals(6, strides.size());
            assertEquals(t(24), strides.get(2).tNs());
            assertEquals(t(39), strides.get(5).tNs());

            PednavException x = assertThrows(PednavException.class,
                    () -> e.reconfigure("step_detector", "{\"every_nn\": 3}"));
            assertEquals(PednavException.INVALID_CONFIG, x.status());
            assertEquals("/params/every_nn", x.where());
            x = assertThrows(PednavException.class, () -> e.reconfigure("map_matcher", "{}"));
            assertEquals(PednavException.NOT_FOUND, x.status());
            x = assertThrows(PednavException.class,
                    () -> e.reconfigure("foot/step_detector", "{\"latency_samples\": 2}"));
            assertEquals(PednavException.UNSUPPORTED, x.status());
        }
    }
}
