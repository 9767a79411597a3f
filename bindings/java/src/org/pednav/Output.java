// SPDX-License-Identifier: Apache-2.0
package org.pednav;

/**
 * One output record polled from an engine: a {@link Position}, a
 * {@link Stride} or a {@link Step}. Immutable.
 */
public abstract class Output {
    private final long tNs;
    private final int sourceId;
    private final int flags;

    Output(long tNs, int sourceId, int flags) {
        this.tNs = tNs;
        this.sourceId = sourceId;
        this.flags = flags;
    }

    /** The time the record describes, on the clock of the pushed samples (ns). */
    public final long tNs() {
        return tNs;
    }

    /** The engine's index of the producing stage + 1 (0 would be an app input). */
    public final int sourceId() {
        return sourceId;
    }

    /** The record's {@code PN_*_FLAG_*} bits. */
    public final int flags() {
        return flags;
    }

    boolean sameHeader(Output o) {
        return tNs == o.tNs && sourceId == o.sourceId && flags == o.flags;
    }

    int headerHash() {
        return (Long.hashCode(tNs) * 31 + sourceId) * 31 + flags;
    }

    /** Bit-exact comparison of doubles (NaN equals NaN, 0.0 differs from -0.0). */
    static boolean same(double a, double b) {
        return Double.doubleToLongBits(a) == Double.doubleToLongBits(b);
    }
}
