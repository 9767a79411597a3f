// SPDX-License-Identifier: Apache-2.0
package org.pednav;

import java.nio.charset.StandardCharsets;
import java.util.concurrent.atomic.AtomicLong;

/**
 * What the JNI glue calls for each logged line: decodes the UTF-8 text and
 * calls the app's {@link LogListener}, catching whatever it throws so that no
 * exception is pending when control returns to the engine. The glue holds it
 * through a weak reference; its {@link Engine} holds it strongly.
 */
final class LogSink {
    private final LogListener listener;
    private final AtomicLong failures = new AtomicLong();

    LogSink(LogListener listener) {
        this.listener = listener;
    }

    long failures() {
        return failures.get();
    }

    /** Called by pednav_jni.c (deliver_log). */
    static void deliver(LogSink sink, int level, byte[] source, byte[] message) {
        try {
            sink.listener.log(level, new String(source, StandardCharsets.UTF_8),
                    new String(message, StandardCharsets.UTF_8));
        } catch (Throwable t) { // nothing may cross back into the engine
            sink.failures.incrementAndGet();
        }
    }
}
