#include "pednav_foot/ekf15.hpp"

namespace pednav::foot {

void Ekf15::reset_covariance(const double* diag) {
    std::memset(P_, 0, sizeof P_);
    std::memset(x_, 0, sizeof x_);
    if (diag)
        for (int i = 0; i < N; ++i) P_[i][i] = diag[i];
}

void Ekf15::propagate(double dt, const Mat3& R, const Vec3& f, const Noise& q) {
    // Phi = I + G with G nonzero only in rows ATT, POS, VEL:
    //   G[ATT,BG] = -R dt, G[POS,VEL] = I dt, G[VEL,ATT] = -skew(f) dt, G[VEL,BA] = -R dt.
    // Phi P Phi^T = P + N + N^T + N_G where N = G P and N_G = G P G^T, written
    // so that the result is exactly symmetric.
    double Rd[3][3], Sd[3][3];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) Rd[r][c] = -R(r, c) * dt;
    const Mat3 s = skew(f);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) Sd[r][c] = -s(r, c) * dt;

    // N = G P (rows ATT, POS, VEL only; 9 x 15).
    double Nm[9][N];
    for (int r = 0; r < 3; ++r) {
        double* na = Nm[r];
        double* np = Nm[3 + r];
        double* nv = Nm[6 + r];
        const double* pv = P_[VEL + r];
        for (int c = 0; c < N; ++c) {
            na[c] = Rd[r][0] * P_[BG][c] + Rd[r][1] * P_[BG + 1][c] + Rd[r][2] * P_[BG + 2][c];
            np[c] = dt * pv[c];
            nv[c] = Sd[r][0] * P_[ATT][c] + Sd[r][1] * P_[ATT + 1][c] + Sd[r][2] * P_[ATT + 2][c] +
                    Rd[r][0] * P_[BA][c] + Rd[r][1] * P_[BA + 1][c] + Rd[r][2] * P_[BA + 2][c];
        }
    }
    // N_G = N G^T restricted to rows/cols (ATT, POS, VEL): entry (a, b) =
    // sum_k N[a][k] G[b][k]. Upper triangle, mirrored.
    static constexpr int kRows[9] = {ATT, ATT + 1, ATT + 2, POS, POS + 1, POS + 2, VEL, VEL + 1, VEL + 2};
    double NG[9][9];
    for (int a = 0; a < 9; ++a) {
        const double* na = Nm[a];
        for (int b = a; b < 9; ++b) {
            double v;
            if (b < 3) {
                v = Rd[b][0] * na[BG] + Rd[b][1] * na[BG + 1] + Rd[b][2] * na[BG + 2];
            } else if (b < 6) {
                v = dt * na[VEL + b - 3];
            } else {
                const int r = b - 6;
                v = Sd[r][0] * na[ATT] + Sd[r][1] * na[ATT + 1] + Sd[r][2] * na[ATT + 2] +
                    Rd[r][0] * na[BA] + Rd[r][1] * na[BA + 1] + Rd[r][2] * na[BA + 2];
            }
            NG[a][b] = v;
            NG[b][a] = v;
        }
    }
    // P += N + N^T + N_G, each entry computed once and mirrored.
    static constexpr int kOther[6] = {BG, BG + 1, BG + 2, BA, BA + 1, BA + 2};
    for (int a = 0; a < 9; ++a) {
        const int ra = kRows[a];
        for (int o = 0; o < 6; ++o) {
            const int c = kOther[o];
            const double v = P_[ra][c] + Nm[a][c];
            P_[ra][c] = v;
            P_[c][ra] = v;
        }
        for (int b = a; b < 9; ++b) {
            const int rb = kRows[b];
            const double v = P_[ra][rb] + (Nm[a][rb] + Nm[b][ra]) + NG[a][b];
            P_[ra][rb] = v;
            P_[rb][ra] = v;
        }
    }
    // Q (isotropic densities, so R Q R^T = Q).
    const double qa = q.gyro_psd * dt, qv = q.accel_psd * dt;
    const double qbg = q.gyro_bias_psd * dt, qba = q.accel_bias_psd * dt;
    for (int i = 0; i < 3; ++i) {
        P_[ATT + i][ATT + i] += qa;
        P_[VEL + i][VEL + i] += qv;
        P_[BG + i][BG + i] += qbg;
        P_[BA + i][BA + i] += qba;
    }
}

void Ekf15::update_scalar(int i, double z, double var) {
    double c[N];
    for (int k = 0; k < N; ++k) c[k] = P_[k][i];
    const double s = c[i] + var;  // H P H^T + R: a copy of P_ii
    if (!(s > 0)) return;
    double K[N];
    const double inv = 1.0 / s;
    for (int k = 0; k < N; ++k) K[k] = c[k] * inv;
    const double innov = z - x_[i];
    for (int k = 0; k < N; ++k) x_[k] += K[k] * innov;
    // Joseph form (I - K e_i^T) P (I - K e_i^T)^T + K var K^T, expanded for
    // H = e_i: P - K c^T - c K^T + (c_i + var) K K^T. Upper triangle, mirrored.
    for (int a = 0; a < N; ++a) {
        const double ka = K[a], ca = c[a], ska = s * K[a];
        double* pa = P_[a];
        for (int b = a; b < N; ++b) {
            const double v = pa[b] + ((ska * K[b] - ka * c[b]) - ca * K[b]);
            pa[b] = v;
            P_[b][a] = v;
        }
    }
}

}  // namespace pednav::foot
