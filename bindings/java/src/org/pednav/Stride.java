// SPDX-License-Identifier: Apache-2.0
package org.pednav;

import java.util.Arrays;

/**
 * One step's displacement ({@code pn_stride_t}), emitted once per step by a
 * position filter. {@link #tNs()} is the end of the step. Immutable; array
 * getters return copies.
 */
public final class Stride extends Output {
    /** {@code PN_STRIDE_CLASS_*}. */
    public static final int CLASS_UNKNOWN = 0, CLASS_LEVEL = 1, CLASS_STAIRS_UP = 2, CLASS_STAIRS_DOWN = 3;

    private final long tStartNs;
    private final double[] displacementEnuM;
    private final double lengthM;
    private final double headingChangeRad;
    private final double[] covDisplacementM2;
    private final int strideClass;
    private final int index;

    /** From the JNI scratch layout (see Engine.poll). */
    Stride(long[] l, double[] d) {
        super(l[0], (int) l[1], (int) l[2]);
        tStartNs = l[3];
        strideClass = (int) l[5];
        index = (int) l[6];
        displacementEnuM = Arrays.copyOfRange(d, 0, 3);
        lengthM = d[3];
        headingChangeRad = d[4];
        covDisplacementM2 = Arrays.copyOfRange(d, 5, 14);
    }

    public long tStartNs() {
        return tStartNs;
    }

    /** East, north, up displacement over the step in metres (a copy). */
    public double[] displacementEnuM() {
        return displacementEnuM.clone();
    }

    /** Horizontal length in metres. */
    public double lengthM() {
        return lengthM;
    }

    /** Heading change over the step, clockwise positive, radians. */
    public double headingChangeRad() {
        return headingChangeRad;
    }

    /** Displacement covariance in m^2, row-major 3x3 (a copy). */
    public double[] covDisplacementM2() {
        return covDisplacementM2.clone();
    }

    /** One of the CLASS_* constants. */
    public int strideClass() {
        return strideClass;
    }

    /** 0, 1, 2, ... since the last reset. */
    public int index() {
        return index;
    }

    /** Bit-exact equality of every field. */
    @Override
    public boolean equals(Object o) {
        if (this == o) return true;
        if (!(o instanceof Stride)) return false;
        Stride s = (Stride) o;
        return sameHeader(s) && tStartNs == s.tStartNs && Arrays.equals(displacementEnuM, s.displacementEnuM)
                && same(lengthM, s.lengthM) && same(headingChangeRad, s.headingChangeRad)
                && Arrays.equals(covDisplacementM2, s.covDisplacementM2) && strideClass == s.strideClass
                && index == s.index;
    }

    @Override
    public int hashCode() {
        int h = headerHash();
        h = 31 * h + Arrays.hashCode(displacementEnuM);
        h = 31 * h + Double.hashCode(lengthM);
        return 31 * h + index;
    }

    @Override
    public String toString() {
        return "Stride{t_ns=" + tNs() + ", index=" + index + ", displacement_enu_m=" + Arrays.toString(displacementEnuM)
                + ", length_m=" + lengthM + ", heading_change_rad=" + headingChangeRad + ", class=" + strideClass + "}";
    }
}
