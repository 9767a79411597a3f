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

    /** From a polled pn_stride_t. */
    Stride(RecordLayout.Slot s) {
        super(s);
        tStartNs = s.i64(RecordLayout.STRIDE_T_START);
        displacementEnuM = s.f64s(RecordLayout.STRIDE_DISP, 3);
        lengthM = s.f64(RecordLayout.STRIDE_LENGTH);
        headingChangeRad = s.f64(RecordLayout.STRIDE_DHEADING);
        covDisplacementM2 = s.f64s(RecordLayout.STRIDE_COV, 9);
        strideClass = s.i32(RecordLayout.STRIDE_CLASS);
        index = s.i32(RecordLayout.STRIDE_INDEX);
    }

    /** Start of the step (ns). */
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
