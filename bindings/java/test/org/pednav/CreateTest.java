// SPDX-License-Identifier: Apache-2.0
package org.pednav;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.pednav.TestSupport.config;
import static org.pednav.TestSupport.fixtureConfig;
import static org.pednav.TestSupport.fixtureDir;
import static org.pednav.TestSupport.stage;

import org.junit.jupiter.api.Test;

/** Engine.create: config and plugin errors as PednavException, and what a good engine reports. */
class CreateTest {
    @Test
    void unknownParamKeyNamesTheKey() {
        String cfg = config(stage("step_detector", "org.pednav.test.counting_steps", "\"every_nn\": 3"),
                stage("position_filter", "org.pednav.test.step_counter", ""));
        PednavException e = assertThrows(PednavException.class, () -> Engine.create(cfg, fixtureDir("good")));
        assertEquals(PednavException.INVALID_CONFIG, e.status());
        assertEquals("PN_E_INVALID_CONFIG", e.statusName());
        assertEquals("/pipelines/foot/step_detector/params/every_nn", e.where());
        assertTrue(e.errorMessage().contains("every_nn"), e.errorMessage());
        assertTrue(e.getMessage().startsWith("PN_E_INVALID_CONFIG at /pipelines/foot/step_detector/params/every_nn: "),
                e.getMessage());
    }

    @Test
    void outOfRangeParamNamesTheKey() {
        String cfg = config(stage("step_detector", "org.pednav.test.counting_steps", "\"every_n\": 0"));
        PednavException e = assertThrows(PednavException.class, () -> Engine.create(cfg, fixtureDir("good")));
        assertEquals("PN_E_INVALID_CONFIG", e.statusName());
        assertEquals("/pipelines/foot/step_detector/params/every_n", e.where());
    }

    @Test
    void misspelledRoleAndBadFormatNameTheKey() {
        String role = config(stage("step_detektor", "org.pednav.test.counting_steps", ""));
        PednavException e = assertThrows(PednavException.class, () -> Engine.create(role, fixtureDir("good")));
        assertEquals("PN_E_INVALID_CONFIG", e.statusName());
        assertEquals("/pipelines/foot/step_detektor", e.where());

        String format = config(stage("step_detector", "org.pednav.test.counting_steps", ""))
                .replace("pednav-config/1", "pednav-config/9");
        e = assertThrows(PednavException.class, () -> Engine.create(format, fixtureDir("good")));
        assertEquals("/format", e.where());
    }

    @Test
    void pluginNotInTheGivenFoldersNamesThePluginKey() {
        // Right config, but no plugin folder: the plugin cannot be found.
        String cfg = fixtureConfig(10, 0, 0.0, 0.7);
        PednavException e = assertThrows(PednavException.class, () -> Engine.create(cfg));
        assertTrue(e.status() < 0);
        assertEquals("/pipelines/foot/step_detector/plugin", e.where());
        assertTrue(e.errorMessage().contains("org.pednav.test.counting_steps"), e.errorMessage());
    }

    @Test
    void nullArgumentsAreJavaExceptions() {
        assertThrows(NullPointerException.class, () -> Engine.create(null, fixtureDir("good")));
        assertThrows(NullPointerException.class,
                () -> Engine.create(fixtureConfig(10, 0, 0.0, 0.7), fixtureDir("good"), null));
    }

    @Test
    void goodEngineReportsVersionLatencyAndPipeline() {
        assertEquals(1, Engine.abiVersion() >>> 16);
        assertEquals(System.getProperty("pednav.test.version"), Engine.version());
        try (Engine e = Engine.create(fixtureConfig(10, 3, 0.0, 0.7), fixtureDir("good"))) {
            assertFalse(e.isClosed());
            // counting_steps declares latency_samples * sample_period_s = 3 * 10 ms.
            assertEquals(30_000_000L, e.latencyNs());
            String d = e.describe();
            assertTrue(d.startsWith("{") && d.endsWith("}"), d);
            for (String id : new String[] {"org.pednav.test.counting_steps", "org.pednav.test.fixed_heading",
                    "org.pednav.test.step_counter"})
                assertTrue(d.contains("\"" + id + "\""), id + " not in " + d);
            assertEquals(0, TestSupport.counter(e, "records_in"));
        }
    }

    @Test
    void configTextIsPassedAsUtf8() {
        // A non-ASCII, supplementary-plane character in a string value the
        // engine echoes back in its error: it must round-trip unchanged.
        String id = "org.pednav.test.\uD83D\uDEB6";
        String cfg = config(stage("step_detector", id, ""));
        PednavException e = assertThrows(PednavException.class, () -> Engine.create(cfg, fixtureDir("good")));
        assertTrue(e.errorMessage().contains(id), e.errorMessage());
    }
}
