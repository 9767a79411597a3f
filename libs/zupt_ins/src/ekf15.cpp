// SPDX-License-Identifier: Apache-2.0
#include "pednav_zupt_ins/ekf15.hpp"

// The covariance kernels are also compiled for AVX (4 doubles per vector) and
// picked at load time on x86-64 with GCC. Only the vector width differs: no
// FMA contraction (AVX has none), no reassociation, so both versions give the
// same bits.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__ELF__)
#define PEDNAV_EKF15_CLONES __attribute__((target_clones("avx", "default")))
#else
#define PEDNAV_EKF15_CLONES
#endif
#if defined(__GNUC__) && !defined(__clang__)
#define PEDNAV_EKF15_UNROLL _Pragma("GCC unroll 16")
// Keeps the compiler from hoisting the loads of later rows of P (it would
// spill them): each row is loaded, updated and stored in turn.
#define PEDNAV_EKF15_ROW_BARRIER __asm__ __volatile__("" ::: "memory");
#else
#define PEDNAV_EKF15_ROW_BARRIER
#define PEDNAV_EKF15_UNROLL
#endif
// The update kernels and the transition terms are always inlined into their callers.
#define PEDNAV_EKF15_INLINE inline __attribute__((always_inline))

namespace {

// Four doubles as one value (GCC/Clang vector extension): one AVX register in
// the AVX clones, two SSE2 registers otherwise. Element-wise IEEE arithmetic
// in the order written, so the results are the bits of the scalar expressions.
typedef double v4d __attribute__((vector_size(32)));
typedef long long v4i __attribute__((vector_size(32)));

}  // namespace

// Load and store four doubles at a 32-byte aligned address (macros, not
// functions: a vector passed by value would change the ABI between clones).
#define ld4(p) (*reinterpret_cast<const v4d*>(p))
#define st4(p, v) (*reinterpret_cast<v4d*>(p) = (v))
// Lanes i0..i3 of the eight of (a, b): GCC's __builtin_shuffle takes them as a
// vector, Clang's __builtin_shufflevector as constants (same lanes, same bits).
#if defined(__clang__)
#define shuffle4(a, b, i0, i1, i2, i3) __builtin_shufflevector(a, b, i0, i1, i2, i3)
#else
#define shuffle4(a, b, i0, i1, i2, i3) \
    __builtin_shuffle(a, b, (__extension__(v4i){i0, i1, i2, i3}))
#endif

namespace pednav::zupt_ins {

using navmath::skew;

namespace {

// The rows of P that a transition I + E changes, E nonzero in rows ATT, POS, VEL.
constexpr int ATT = Ekf15::ATT, BG = Ekf15::BG, POS = Ekf15::POS, VEL = Ekf15::VEL, BA = Ekf15::BA;
constexpr int NP = Ekf15::NP;

// (I + E) P (I + E)^T = P + N + N^T + N_G with N = E P (its rows ATT, POS,
// VEL in Nm, 9 x 16) and N_G = E P E^T, whose entry between the changed rows
// a <= b (indices 0..8 into ATT, POS, VEL) ng(a, b) returns.
template <class NG>
PEDNAV_EKF15_INLINE void add_transition_terms(double (*P_)[NP], const double (*Nm)[NP], NG ng) {
    // P += N + N^T + N_G. Entries between the changed rows (ATT, POS, VEL) add
    // N(a, b) + N(b, a), a commutative sum, and N_G from its upper triangle;
    // entries against BG, BA get N once. Each value is written to the upper
    // triangle only (its one copy): exactly symmetric.
    static constexpr int kRows[9] = {ATT, ATT + 1, ATT + 2, POS, POS + 1, POS + 2, VEL, VEL + 1, VEL + 2};
    PEDNAV_EKF15_UNROLL
    for (int a = 0; a < 9; ++a) {
        PEDNAV_EKF15_ROW_BARRIER
        const int ra = kRows[a];
        const double* na = Nm[a];
        double* pa = P_[ra];
        // BA columns (12..14, and the zero padding 15): one vector.
        st4(pa + BA, ld4(pa + BA) + ld4(na + BA));
        PEDNAV_EKF15_UNROLL
        for (int o = 0; o < 3; ++o) {
            const int c = BG + o;
            if (ra < c) pa[c] = pa[c] + na[c];
            else P_[c][ra] = P_[c][ra] + na[c];
        }
        PEDNAV_EKF15_UNROLL
        for (int b = a; b < 9; ++b) {
            const int rb = kRows[b];
            pa[rb] = pa[rb] + (na[rb] + Nm[b][ra]) + ng(a, b);
        }
    }
}

}  // namespace

void Ekf15::reset_covariance(const double* diag) {
    std::memset(P_, 0, sizeof P_);
    std::memset(x_, 0, sizeof x_);
    deferred_.clear();
    if (diag)
        for (int i = 0; i < N; ++i) P_[i][i] = diag[i];
}

PEDNAV_EKF15_CLONES
void Ekf15::mirror_lower() {
    // propagate() reads whole rows ATT, BG, VEL, BA; the rows of POS are read
    // from the upper triangle only, so their lower parts are not restored.
    // Fully unrolled: one load and one store per entry.
    PEDNAV_EKF15_UNROLL
    for (int a = 1; a < POS; ++a) {
        PEDNAV_EKF15_UNROLL
        for (int b = 0; b < a; ++b) P_[a][b] = P_[b][a];
    }
    PEDNAV_EKF15_UNROLL
    for (int a = VEL; a < N; ++a) {
        PEDNAV_EKF15_UNROLL
        for (int b = 0; b < a; ++b) P_[a][b] = P_[b][a];
    }
}


PEDNAV_EKF15_CLONES
void Ekf15::propagate(double dt, const Mat3& R, const Vec3& f, const Noise& q) {
    apply_deferred();
    // The products below read whole rows of P: restore the lower triangle.
    mirror_lower();
    // Phi = I + G with G nonzero only in rows ATT, POS, VEL:
    //   G[ATT,BG] = -R dt, G[POS,VEL] = I dt, G[VEL,ATT] = -skew(f) dt, G[VEL,BA] = -R dt.
    // Phi P Phi^T = P + N + N^T + N_G where N = G P and N_G = G P G^T, written
    // so that the result is exactly symmetric.
    double Rd[3][3];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) Rd[r][c] = -R(r, c) * dt;
    // -skew(f) dt = skew(-f dt) = [[0, fz, -fy], [-fz, 0, fx], [fy, -fx, 0]], written out below.
    const double fx = f.x() * dt, fy = f.y() * dt, fz = f.z() * dt;

    // N = G P, rows ATT, POS, VEL (9 x 16).
    // Four columns at a time; the constants are broadcast once.
    alignas(64) double Nm[9][NP];
    PEDNAV_EKF15_UNROLL
    for (int c = 0; c < NP; c += 4) {
        PEDNAV_EKF15_ROW_BARRIER
        const v4d b0 = ld4(P_[BG] + c), b1 = ld4(P_[BG + 1] + c), b2 = ld4(P_[BG + 2] + c);
        PEDNAV_EKF15_UNROLL
        for (int r = 0; r < 3; ++r) {
            st4(Nm[r] + c, Rd[r][0] * b0 + Rd[r][1] * b1 + Rd[r][2] * b2);
            st4(Nm[3 + r] + c, dt * ld4(P_[VEL + r] + c));
        }
        const v4d a0 = ld4(P_[ATT] + c), a1 = ld4(P_[ATT + 1] + c), a2 = ld4(P_[ATT + 2] + c);
        const v4d e0 = ld4(P_[BA] + c), e1 = ld4(P_[BA + 1] + c), e2 = ld4(P_[BA + 2] + c);
        st4(Nm[6] + c, fz * a1 - fy * a2 + Rd[0][0] * e0 + Rd[0][1] * e1 + Rd[0][2] * e2);
        st4(Nm[7] + c, -fz * a0 + fx * a2 + Rd[1][0] * e0 + Rd[1][1] * e1 + Rd[1][2] * e2);
        st4(Nm[8] + c, fy * a0 - fx * a1 + Rd[2][0] * e0 + Rd[2][1] * e1 + Rd[2][2] * e2);
    }
    // N_G = N G^T restricted to rows/cols (ATT, POS, VEL); column b of G^T is
    // row b of G: (Rd on BG) for ATT, (dt on VEL) for POS, (-skew(f) dt on ATT,
    // Rd on BA) for VEL. Only the 3 x 3 blocks on or above the block diagonal
    // are computed (the loop below reads NG[a][b] for b >= a only); the VEL
    // columns, needed for all nine rows, as vectors over a (NV[r][a] = NG[a][6 + r])
    // from the ATT and BA columns of N transposed into rows.
    double NG[9][6];
    PEDNAV_EKF15_UNROLL
    for (int a = 0; a < 6; ++a) {
        const double* na = Nm[a];
        double* ng = NG[a];
        if (a < 3) {
            const double g0 = na[BG], g1 = na[BG + 1], g2 = na[BG + 2];
            for (int r = 0; r < 3; ++r) ng[r] = Rd[r][0] * g0 + Rd[r][1] * g1 + Rd[r][2] * g2;
        }
        for (int r = 0; r < 3; ++r) ng[3 + r] = dt * na[VEL + r];
    }
    // NV by 4 x 4 transposes of N's ATT and BA columns (rows 0-3, 4-7, 8 and
    // zeros): lanes over a, the same expressions as scalars.
    alignas(64) double NV[3][12];
    {
        const v4d zero = {0.0, 0.0, 0.0, 0.0};
        const double r00 = Rd[0][0], r01 = Rd[0][1], r02 = Rd[0][2];
        const double r10 = Rd[1][0], r11 = Rd[1][1], r12 = Rd[1][2];
        const double r20 = Rd[2][0], r21 = Rd[2][1], r22 = Rd[2][2];
        PEDNAV_EKF15_UNROLL
        for (int k = 0; k < 12; k += 4) {
            v4d t[3], e[3];
            for (int part = 0; part < 2; ++part) {
                const int col = part == 0 ? ATT : BA;
                const v4d m0 = ld4(Nm[k] + col);
                const v4d m1 = k + 1 < 9 ? ld4(Nm[k + 1] + col) : zero;
                const v4d m2 = k + 2 < 9 ? ld4(Nm[k + 2] + col) : zero;
                const v4d m3 = k + 3 < 9 ? ld4(Nm[k + 3] + col) : zero;
                const v4d u0 = shuffle4(m0, m1, 0, 4, 2, 6), u1 = shuffle4(m0, m1, 1, 5, 3, 7);
                const v4d u2 = shuffle4(m2, m3, 0, 4, 2, 6), u3 = shuffle4(m2, m3, 1, 5, 3, 7);
                v4d* out = part == 0 ? t : e;
                out[0] = shuffle4(u0, u2, 0, 1, 4, 5);
                out[1] = shuffle4(u1, u3, 0, 1, 4, 5);
                out[2] = shuffle4(u0, u2, 2, 3, 6, 7);
            }
            st4(NV[0] + k, fz * t[1] - fy * t[2] + r00 * e[0] + r01 * e[1] + r02 * e[2]);
            st4(NV[1] + k, -fz * t[0] + fx * t[2] + r10 * e[0] + r11 * e[1] + r12 * e[2]);
            st4(NV[2] + k, fy * t[0] - fx * t[1] + r20 * e[0] + r21 * e[1] + r22 * e[2]);
        }
    }
    add_transition_terms(P_, Nm, [&](int a, int b) { return b < 6 ? NG[a][b] : NV[b - 6][a]; });
    // Q (isotropic densities, so R Q R^T = Q).
    add_noise(NoiseVariance::over(q, dt));
}

void Ekf15::add_noise(const NoiseVariance& q) {
    for (int i = 0; i < 3; ++i) {
        P_[ATT + i][ATT + i] += q.att_rad2;
        P_[VEL + i][VEL + i] += q.vel_m2ps2;
        P_[BG + i][BG + i] += q.gyro_bias_rad2ps2;
        P_[BA + i][BA + i] += q.accel_bias_m2ps4;
    }
}

PEDNAV_EKF15_CLONES
void Ekf15::SwingTransition::add(double dt, const Mat3& R, const Vec3& f, const Noise& q) {
    // The POS blocks first (they take the values before this interval), then
    // VB (with C before it), dv_mps and C.
    const v4d c0 = ld4(C[0]), c1 = ld4(C[1]), c2 = ld4(C[2]);
    st4(PB[0], ld4(PB[0]) + dt * ld4(VB[0]));
    st4(PB[1], ld4(PB[1]) + dt * ld4(VB[1]));
    st4(PB[2], ld4(PB[2]) + dt * ld4(VB[2]));
    st4(PE[0], ld4(PE[0]) + dt * c0);
    st4(PE[1], ld4(PE[1]) + dt * c1);
    st4(PE[2], ld4(PE[2]) + dt * c2);
    st4(dp_m, ld4(dp_m) + dt * ld4(dv_mps));
    // VB += -skew(f dt) C, written out as in propagate()
    const double fx = f.x() * dt, fy = f.y() * dt, fz = f.z() * dt;
    st4(VB[0], ld4(VB[0]) + (fz * c1 - fy * c2));
    st4(VB[1], ld4(VB[1]) + (fx * c2 - fz * c0));
    st4(VB[2], ld4(VB[2]) + (fy * c0 - fx * c1));
    const v4d fd = {fx, fy, fz, 0.0};
    st4(dv_mps, ld4(dv_mps) + fd);
    for (int r = 0; r < 3; ++r) {
        const v4d row = {R(r, 0), R(r, 1), R(r, 2), 0.0};
        st4(C[r], ld4(C[r]) - dt * row);
    }
    t_s += dt;
    q_sum += NoiseVariance::over(q, dt);
}

PEDNAV_EKF15_CLONES
void Ekf15::apply_transition() {
    const SwingTransition& m = deferred_;
    const NoiseVariance half_q = m.q_sum.scaled(0.5);
    add_noise(half_q);
    mirror_lower();
    // The skew blocks E(VEL, ATT) = -skew(dv) = skew(-dv) and E(POS, ATT) = skew(-dp),
    // row-major so that a row is contiguous.
    using RowMat3 = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;
    const RowMat3 VA = skew(-Vec3::Map(m.dv_mps)), PA = skew(-Vec3::Map(m.dp_m));
    const double t = m.t_s;
    // N = E P, rows ATT, POS, VEL (9 x 16), four columns at a time.
    alignas(64) double Nm[9][NP];
    PEDNAV_EKF15_UNROLL
    for (int c = 0; c < NP; c += 4) {
        PEDNAV_EKF15_ROW_BARRIER
        const v4d a0 = ld4(P_[ATT] + c), a1 = ld4(P_[ATT + 1] + c), a2 = ld4(P_[ATT + 2] + c);
        const v4d b0 = ld4(P_[BG] + c), b1 = ld4(P_[BG + 1] + c), b2 = ld4(P_[BG + 2] + c);
        const v4d e0 = ld4(P_[BA] + c), e1 = ld4(P_[BA + 1] + c), e2 = ld4(P_[BA + 2] + c);
        PEDNAV_EKF15_UNROLL
        for (int r = 0; r < 3; ++r) {
            const v4d cb = m.C[r][0] * b0 + m.C[r][1] * b1 + m.C[r][2] * b2;
            st4(Nm[r] + c, cb);
            st4(Nm[3 + r] + c, PA(r, 0) * a0 + PA(r, 1) * a1 + PA(r, 2) * a2 +
                                   (m.PB[r][0] * b0 + m.PB[r][1] * b1 + m.PB[r][2] * b2) + t * ld4(P_[VEL + r] + c) +
                                   (m.PE[r][0] * e0 + m.PE[r][1] * e1 + m.PE[r][2] * e2));
            st4(Nm[6 + r] + c, VA(r, 0) * a0 + VA(r, 1) * a1 + VA(r, 2) * a2 +
                                   (m.VB[r][0] * b0 + m.VB[r][1] * b1 + m.VB[r][2] * b2) +
                                   (m.C[r][0] * e0 + m.C[r][1] * e1 + m.C[r][2] * e2));
        }
    }
    // N_G = N E^T between the changed rows, upper triangle (b >= a): column b
    // of E^T is row b of E.
    double NG[9][9];
    PEDNAV_EKF15_UNROLL
    for (int a = 0; a < 9; ++a) {
        const double* n = Nm[a];
        PEDNAV_EKF15_UNROLL
        for (int b = a; b < 9; ++b) {
            const int r = b % 3;
            const auto dot3 = [&](int col, const double* e) { return n[col] * e[0] + n[col + 1] * e[1] + n[col + 2] * e[2]; };
            if (b < 3) NG[a][b] = dot3(BG, m.C[r]);
            else if (b < 6)
                NG[a][b] = dot3(ATT, &PA(r, 0)) + dot3(BG, m.PB[r]) + t * n[VEL + r] + dot3(BA, m.PE[r]);
            else NG[a][b] = dot3(ATT, &VA(r, 0)) + dot3(BG, m.VB[r]) + dot3(BA, m.C[r]);
        }
    }
    add_transition_terms(P_, Nm, [&](int a, int b) { return NG[a][b]; });
    add_noise(half_q);
    deferred_.clear();
}


// The update kernels are written once, always inlined, and called with the
// state index as a literal for the indices the foot INS uses (ZUPT at VEL,
// ZARU at BG, HUPT at POS + 2), so that every loop has constant bounds.

PEDNAV_EKF15_INLINE void Ekf15::scalar_kernel(int i, double z, double var) {
    alignas(64) double c[NP];
    column_inline(i, c);                          // P H^T: a copy of column i
    const double s = c[i] + var;                  // H P H^T + R: a copy of P_ii
    if (!(s > 0)) return;
    alignas(64) double K[NP];
    const double inv = 1.0 / s;
    for (int k = 0; k < NP; k += 4) st4(K + k, ld4(c + k) * inv);
    const double innov = z - x_[i];
    for (int k = 0; k < NP; k += 4) st4(x_ + k, ld4(x_ + k) + ld4(K + k) * innov);
    if (!joseph_) {
        // P - K c^T: entry (a, b) = P_ab - (c_a c_b) / s, upper triangle.
        // Rows start at a multiple of 4 (four-wide vectors); the entries
        // below the diagonal that this touches are stale anyway.
        PEDNAV_EKF15_UNROLL
        for (int g = 0; g < N; g += 4) {
            for (int a = g; a < g + 4 && a < N; ++a) {
                PEDNAV_EKF15_ROW_BARRIER
                const double ca = c[a] * inv;
                double* pa = P_[a];
                PEDNAV_EKF15_UNROLL
                for (int b = g; b < NP; b += 4) st4(pa + b, ld4(pa + b) - ca * ld4(c + b));
            }
        }
        return;
    }
    // Joseph form (I - K e_i^T) P (I - K e_i^T)^T + K var K^T (eq. (33)),
    // expanded for H = e_i: P + s K K^T - (K c^T + c K^T). Upper triangle
    // only (rows from a multiple of 4, as above): symmetric by construction.
    PEDNAV_EKF15_UNROLL
    for (int g = 0; g < N; g += 4) {
        for (int a = g; a < g + 4 && a < N; ++a) {
            PEDNAV_EKF15_ROW_BARRIER
            const double ka = K[a], ca = c[a], ska = s * ka;
            double* pa = P_[a];
            PEDNAV_EKF15_UNROLL
            for (int b = g; b < NP; b += 4) {
                const v4d Kb = ld4(K + b);
                st4(pa + b, ld4(pa + b) + (ska * Kb - (ka * ld4(c + b) + ca * Kb)));
            }
        }
    }
}

PEDNAV_EKF15_CLONES
void Ekf15::update_scalar(int i, double z, double var) {
    apply_deferred();
    if (i == POS + 2) scalar_kernel(POS + 2, z, var);
    else scalar_kernel(i, z, var);
}

PEDNAV_EKF15_INLINE void Ekf15::block3_kernel(int i0, const double z[3], const double var[3], uint32_t hold_mask) {
    // C = P H^T (columns i0..i0+2, copies), S = H P H^T + R (a copied block).
    // C, K and W are kept transposed (3 rows of 16) so that the loops over
    // the states run along contiguous memory; their padding entries are zero
    // (products of the zero padding of C).
    alignas(64) double CT[3][NP];
    for (int j = 0; j < 3; ++j) column_inline(i0 + j, CT[j]);
    double S[3][3];
    for (int r = 0; r < 3; ++r)
        for (int j = 0; j < 3; ++j) S[r][j] = CT[j][i0 + r];
    for (int j = 0; j < 3; ++j) S[j][j] += var[j];
    // S^-1 by the adjugate (S symmetric positive definite).
    const double a00 = S[1][1] * S[2][2] - S[1][2] * S[2][1];
    const double a01 = S[0][2] * S[2][1] - S[0][1] * S[2][2];
    const double a02 = S[0][1] * S[1][2] - S[0][2] * S[1][1];
    const double det = S[0][0] * a00 + S[1][0] * a01 + S[2][0] * a02;
    if (!(det > 0)) return;
    const double id = 1.0 / det;
    double Si[3][3];
    Si[0][0] = a00 * id;
    Si[0][1] = a01 * id;
    Si[0][2] = a02 * id;
    Si[1][1] = (S[0][0] * S[2][2] - S[0][2] * S[2][0]) * id;
    Si[1][2] = (S[0][2] * S[1][0] - S[0][0] * S[1][2]) * id;
    Si[2][2] = (S[0][0] * S[1][1] - S[0][1] * S[1][0]) * id;
    Si[1][0] = Si[0][1];
    Si[2][0] = Si[0][2];
    Si[2][1] = Si[1][2];
    // K = C S^-1 (eq. (31)), as K^T.
    alignas(64) double KT[3][NP];
    PEDNAV_EKF15_UNROLL
    for (int j = 0; j < 3; ++j) {
        const double s0 = Si[0][j], s1 = Si[1][j], s2 = Si[2][j];
        PEDNAV_EKF15_UNROLL
        for (int k = 0; k < NP; k += 4)
            st4(KT[j] + k, ld4(CT[0] + k) * s0 + ld4(CT[1] + k) * s1 + ld4(CT[2] + k) * s2);
    }
    if (hold_mask)
        for (int k = 0; k < N; ++k)
            if (hold_mask & (1u << k)) KT[0][k] = KT[1][k] = KT[2][k] = 0.0;
    // State (eq. (30)); x_[15] is padding and stays zero.
    const double e0 = z[0] - x_[i0], e1 = z[1] - x_[i0 + 1], e2 = z[2] - x_[i0 + 2];
    PEDNAV_EKF15_UNROLL
    for (int k = 0; k < NP; k += 4)
        st4(x_ + k, ld4(x_ + k) + (ld4(KT[0] + k) * e0 + ld4(KT[1] + k) * e1 + ld4(KT[2] + k) * e2));
    if (!joseph_ && !hold_mask) {
        // P - K C^T (K C^T = C S^-1 C^T is symmetric): upper triangle, rows
        // from a multiple of 4.
        PEDNAV_EKF15_UNROLL
        for (int g = 0; g < N; g += 4) {
            for (int a = g; a < g + 4 && a < N; ++a) {
                PEDNAV_EKF15_ROW_BARRIER
                const double k0 = KT[0][a], k1 = KT[1][a], k2 = KT[2][a];
                double* pa = P_[a];
                PEDNAV_EKF15_UNROLL
                for (int b = g; b < NP; b += 4)
                    st4(pa + b, ld4(pa + b) - (k0 * ld4(CT[0] + b) + k1 * ld4(CT[1] + b) + k2 * ld4(CT[2] + b)));
            }
        }
        return;
    }
    // Joseph form (eq. (33)): P - K C^T - C K^T + K S K^T
    //   = P + K W - C K^T with W = S K^T - C^T (3 x 15). Upper triangle only,
    // rows from a multiple of 4 (the padding column stays zero).
    alignas(64) double W[3][NP];
    PEDNAV_EKF15_UNROLL
    for (int j = 0; j < 3; ++j) {
        const double s0 = S[j][0], s1 = S[j][1], s2 = S[j][2];
        PEDNAV_EKF15_UNROLL
        for (int k = 0; k < NP; k += 4)
            st4(W[j] + k, s0 * ld4(KT[0] + k) + s1 * ld4(KT[1] + k) + s2 * ld4(KT[2] + k) - ld4(CT[j] + k));
    }
    PEDNAV_EKF15_UNROLL
    for (int g = 0; g < N; g += 4) {
        for (int a = g; a < g + 4 && a < N; ++a) {
            PEDNAV_EKF15_ROW_BARRIER
            const double k0 = KT[0][a], k1 = KT[1][a], k2 = KT[2][a];
            const double c0 = CT[0][a], c1 = CT[1][a], c2 = CT[2][a];
            double* pa = P_[a];
            PEDNAV_EKF15_UNROLL
            for (int b = g; b < NP; b += 4)
                st4(pa + b, ld4(pa + b) + ((k0 * ld4(W[0] + b) + k1 * ld4(W[1] + b) + k2 * ld4(W[2] + b)) -
                                           (c0 * ld4(KT[0] + b) + c1 * ld4(KT[1] + b) + c2 * ld4(KT[2] + b))));
        }
    }
}

PEDNAV_EKF15_CLONES
void Ekf15::update_block3(int i0, const double z[3], const double var[3], uint32_t hold_mask) {
    apply_deferred();
    if (i0 == VEL) block3_kernel(VEL, z, var, hold_mask);
    else if (i0 == BG) block3_kernel(BG, z, var, hold_mask);
    else block3_kernel(i0, z, var, hold_mask);
}

}  // namespace pednav::zupt_ins
