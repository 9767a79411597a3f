// SPDX-License-Identifier: Apache-2.0
package org.pednav;

/**
 * Receives the lines the engine and its plugins log ({@code pn_log_fn}).
 *
 * <p>Threading: {@link #log} is called synchronously on the thread of the
 * engine call that logs: inside {@link Engine#create} (while plugins
 * initialise), a push, {@link Engine#flush()}, {@link Engine#reset()} or
 * {@link Engine#close()}; never on a thread of its own. Calls for one engine
 * therefore come one at a time, on the producer thread, and a slow listener
 * slows the pipeline down. When an engine that was never closed is freed by
 * its {@link java.lang.ref.Cleaner}, lines its plugins log while being
 * destroyed are dropped (the listener is unreachable by then too) or, if the
 * listener is still reachable from elsewhere, delivered on the Cleaner's
 * thread.
 *
 * <p>A listener should not throw. If it does, the exception is caught and
 * counted ({@link Engine#logListenerFailures()}); the engine's call goes on
 * with its result unchanged, and later lines are delivered as usual.
 */
@FunctionalInterface
public interface LogListener {
    /** {@code PNP_LOG_DEBUG}. */
    int DEBUG = 0;
    /** {@code PNP_LOG_INFO}. */
    int INFO = 1;
    /** {@code PNP_LOG_WARN}: also kept in {@link Engine#describe()}'s warnings. */
    int WARN = 2;
    /** {@code PNP_LOG_ERROR}. */
    int ERROR = 3;

    /**
     * One logged line.
     *
     * @param level {@link #DEBUG}, {@link #INFO}, {@link #WARN} or {@link #ERROR}
     * @param source "engine", an instance name such as "foot/position_filter",
     *     or a plugin id (lines a plugin library's init writes)
     * @param message the line, without a trailing newline
     */
    void log(int level, String source, String message);
}
