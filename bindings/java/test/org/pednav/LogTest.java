// SPDX-License-Identifier: Apache-2.0
package org.pednav;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.pednav.TestSupport.assertSameOutputs;
import static org.pednav.TestSupport.config;
import static org.pednav.TestSupport.fixtureDir;
import static org.pednav.TestSupport.ofType;
import static org.pednav.TestSupport.pushStill;
import static org.pednav.TestSupport.stage;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The log callback through org.pednav.test.logs_everywhere (one line at each
 * level from its library's init, from create, from every process call and
 * from destroy): every line reaches the LogListener, with its source, on the
 * thread of the call that logs; a listener that throws changes nothing.
 */
class LogTest {
    private static final String[] LEVELS = {"debug", "info", "warn", "error"};
    private static final String PLUGIN = "org.pednav.test.logs_everywhere";

    private static String loggingConfig() {
        return config(stage("position_filter", PLUGIN, ""));
    }

    /** One received line. */
    private static final class Line {
        final int level;
        final String source, message;
        final Thread thread;

        Line(int level, String source, String message) {
            this.level = level;
            this.source = source;
            this.message = message;
            this.thread = Thread.currentThread();
        }
    }

    private static long count(List<Line> lines, String source, String message) {
        synchronized (lines) {
            return lines.stream().filter(l -> l.source.equals(source) && l.message.equals(message)).count();
        }
    }

    @Test
    void everyLineReachesTheListenerOnTheThreadThatLogs() throws InterruptedException {
        List<Line> lines = Collections.synchronizedList(new ArrayList<>());
        Engine e = Engine.create(loggingConfig(), (level, source, message) -> lines.add(new Line(level, source, message)),
                fixtureDir("logs_everywhere"));
        for (int level = 0; level < 4; ++level) {
            assertEquals(1, count(lines, PLUGIN, LEVELS[level] + " at init"));
            assertEquals(1, count(lines, "foot/position_filter", LEVELS[level] + " at create"));
        }
        synchronized (lines) {
            for (Line l : lines) {
                assertEquals(Thread.currentThread(), l.thread);
                if (l.source.equals("engine")) // the raw C fixture has no manifest: the loader says so
                    assertTrue(l.level == LogListener.WARN && l.message.contains("no manifest libpnp_logs_everywhere.json"),
                            l.message);
                else
                    assertTrue(l.message.startsWith(LEVELS[l.level] + " at "), l.source + ": " + l.message);
            }
        }
        int beforePush = lines.size();
        assertEquals(13, beforePush); // 4 from init, 4 from create, 4 from latency_ns (asked at create), the loader's warning

        pushStill(e, 0, 21);
        e.flush();
        assertEquals(2, ofType(e.pollAll(), Position.class).size()); // one per 10 samples
        assertEquals(21, count(lines, "foot/position_filter", "debug at process")); // one call per sample time
        assertEquals(21, count(lines, "foot/position_filter", "error at process"));
        assertEquals(beforePush + 4 * 21 + 4, lines.size()); // and flush's four
        assertEquals(0, count(lines, "foot/position_filter", "debug at destroy"));

        // close() on another thread: the destroy lines come on that thread.
        Thread closer = new Thread(e::close, "closer");
        closer.start();
        closer.join();
        for (String l : LEVELS) assertEquals(1, count(lines, "foot/position_filter", l + " at destroy"));
        synchronized (lines) {
            for (Line l : lines.subList(lines.size() - 4, lines.size())) assertEquals(closer, l.thread);
        }
        assertEquals(0, e.logListenerFailures());
    }

    @Test
    void aThrowingListenerIsCaughtCountedAndChangesNoOutput() {
        List<Output> quiet;
        try (Engine e = Engine.create(loggingConfig(), fixtureDir("logs_everywhere"))) {
            pushStill(e, 0, 35);
            e.flush();
            quiet = e.pollAll();
        }
        int[] calls = {0};
        try (Engine e = Engine.create(loggingConfig(), (level, source, message) -> {
            ++calls[0];
            throw new IllegalStateException("listener failure " + calls[0]);
        }, fixtureDir("logs_everywhere"))) {
            assertEquals(13, calls[0]); // as above: init, create, latency_ns, the loader's warning
            assertEquals(13, e.logListenerFailures());
            pushStill(e, 0, 35);
            e.flush();
            assertSameOutputs(quiet, e.pollAll());
            assertEquals(3, ofType(quiet, Position.class).size());
            assertEquals(13 + 4 * 35 + 4, calls[0]); // and flush's four
            assertEquals(calls[0], e.logListenerFailures());
        }
        assertEquals(13 + 4 * 35 + 12, calls[0]); // and flush's, destroy's and the library's deinit's four
    }

    @Test
    void linesOfAFailedCreateStillArrive() {
        // A 100 s look-ahead is refused after both instances exist: the
        // logging filter is created, then destroyed, and says so.
        List<Line> lines = Collections.synchronizedList(new ArrayList<>());
        String cfg = config(stage("step_detector", "org.pednav.test.counting_steps",
                        "\"latency_samples\": 1000, \"sample_period_s\": 0.1"),
                stage("position_filter", PLUGIN, ""));
        PednavException x = assertThrows(PednavException.class, () -> Engine.create(cfg,
                (level, source, message) -> lines.add(new Line(level, source, message)), fixtureDir("good"),
                fixtureDir("logs_everywhere")));
        assertEquals("PN_E_INVALID_CONFIG", x.statusName());
        assertEquals("/pipelines/foot/step_detector", x.where());
        assertEquals(1, count(lines, "foot/position_filter", "debug at create"));
        assertEquals(1, count(lines, "foot/position_filter", "debug at destroy"));
    }
}
