// SPDX-License-Identifier: Apache-2.0
package org.pednav;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.pednav.TestSupport.fixtureConfig;
import static org.pednav.TestSupport.fixtureDir;
import static org.pednav.TestSupport.ofType;
import static org.pednav.TestSupport.pushStill;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;

/**
 * Engines never closed are freed by the Cleaner: the glue's count of native
 * engines alive (created and not destroyed) goes back down once the garbage
 * collector has found them, while engines still referenced stay alive and
 * usable. The wait polls that count against a deadline.
 */
class CleanerTest {
    private static final long DEADLINE_NS = 60_000_000_000L;

    /** Forces collections until the live count is `expected` or the deadline passes; returns the last count. */
    private static long collectUntil(long expected) throws InterruptedException {
        long start = System.nanoTime();
        long live = Engine.liveNativeEngines();
        while (live != expected && System.nanoTime() - start < DEADLINE_NS) {
            System.gc();
            Thread.sleep(5); // lets the Cleaner's thread run the actions the collection queued
            live = Engine.liveNativeEngines();
        }
        return live;
    }

    private static void abandon(int n, boolean listenerHoldsTheEngine) {
        for (int i = 0; i < n; ++i) {
            AtomicReference<Engine> self = new AtomicReference<>();
            LogListener log = listenerHoldsTheEngine ? (level, source, message) -> self.get() : null;
            Engine e = Engine.create(fixtureConfig(10, 0, 0.0, 0.5), log, fixtureDir("good"));
            self.set(e);
            pushStill(e, 0, 15);
        }
    }

    @Test
    void enginesNeverClosedAreFreedAndReferencedOnesStay() throws InterruptedException {
        long before = Engine.liveNativeEngines();
        List<Engine> kept = new ArrayList<>();
        for (int i = 0; i < 3; ++i) kept.add(Engine.create(fixtureConfig(10, 0, 0.0, 0.5), fixtureDir("good")));
        abandon(40, false);
        long peak = Engine.liveNativeEngines();
        System.out.println("live native engines: " + before + " before, " + peak + " after creating 43");
        assertTrue(peak >= before + 3 && peak <= before + 43, "live count " + peak);

        assertEquals(before + 3, collectUntil(before + 3), "abandoned engines were not freed");
        for (int i = 0; i < 3; ++i) System.gc();
        assertEquals(before + 3, Engine.liveNativeEngines(), "an engine still referenced was freed");
        for (Engine e : kept) {
            pushStill(e, 0, 21);
            List<Position> pos = ofType(e.pollAll(), Position.class);
            assertEquals(2, pos.size());
            assertEquals(1.0, pos.get(1).north());
        }
        for (Engine e : kept) e.close();
        assertEquals(before, Engine.liveNativeEngines());
    }

    @Test
    void aListenerHoldingItsEngineDoesNotKeepItAlive() throws InterruptedException {
        // The glue holds the listener weakly: a listener capturing its own
        // engine makes no path from a GC root to the engine.
        long before = Engine.liveNativeEngines();
        abandon(20, true);
        assertEquals(before, collectUntil(before), "engines with a listener holding them were not freed");
    }

    @Test
    void closeFreesAtOnceAndOnlyOnce() throws InterruptedException {
        long before = Engine.liveNativeEngines();
        Engine e = Engine.create(fixtureConfig(10, 0, 0.0, 0.5), fixtureDir("good"));
        assertEquals(before + 1, Engine.liveNativeEngines());
        e.close();
        assertEquals(before, Engine.liveNativeEngines());
        e.close();
        assertEquals(before, Engine.liveNativeEngines());
        e = null;
        // The closed engine, now unreachable, must not be destroyed a second
        // time (the count would go below `before`): wait for a collection to
        // have happened by watching another abandoned engine being freed.
        abandon(1, false);
        assertEquals(before, collectUntil(before));
        for (int i = 0; i < 3; ++i) System.gc();
        assertEquals(before, Engine.liveNativeEngines());
    }
}
