// Unit tests of the foot plugins' shared math (pednav_foot_common): rotations,
// alignment, magnetometer heading, the EKF's covariance algebra, and the
// stance detectors on synthetic signals at several rates.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Eigenvalues>

#include <pednav_foot/ekf15.hpp>
#include <pednav_foot/foot_ins.hpp>
#include <pednav_foot/level_memory.hpp>
#include <pednav_foot/so3.hpp>
#include <pednav_foot/stance_detector.hpp>
#include <pednav_foot/strapdown.hpp>

using namespace pednav::foot;

namespace {
constexpr double kDeg = M_PI / 180.0;

// R_enu_from_body from heading (clockwise from north), pitch (nose up) and roll.
Mat3 attitude(double heading, double pitch, double roll) {
    const double yaw = M_PI / 2 - heading;  // ENU yaw of the body x axis
    return (Eigen::AngleAxisd(yaw, Vec3::UnitZ()) * Eigen::AngleAxisd(-pitch, Vec3::UnitY()) *
            Eigen::AngleAxisd(roll, Vec3::UnitX()))
        .toRotationMatrix();
}

using MatN = Eigen::Matrix<double, 15, 15>;

// The textbook transition and process noise of one interval, dense
// (foot-imu-zupt-zaru-ekf eq. (25)-(26), (32)).
MatN dense_transition(double dt, const Mat3& R, const Vec3& f) {
    MatN Phi = MatN::Identity();
    Phi.block<3, 3>(Ekf15::ATT, Ekf15::BG) = -R * dt;
    Phi.block<3, 3>(Ekf15::POS, Ekf15::VEL) = Mat3::Identity() * dt;
    Phi.block<3, 3>(Ekf15::VEL, Ekf15::ATT) = -skew(f) * dt;
    Phi.block<3, 3>(Ekf15::VEL, Ekf15::BA) = -R * dt;
    return Phi;
}

MatN dense_noise(double dt, const Ekf15::Noise& q) {
    MatN Q = MatN::Zero();
    for (int i = 0; i < 3; ++i) {
        Q(Ekf15::ATT + i, Ekf15::ATT + i) = q.gyro_psd * dt;
        Q(Ekf15::BG + i, Ekf15::BG + i) = q.gyro_bias_psd * dt;
        Q(Ekf15::VEL + i, Ekf15::VEL + i) = q.accel_psd * dt;
        Q(Ekf15::BA + i, Ekf15::BA + i) = q.accel_bias_psd * dt;
    }
    return Q;
}

// A filter whose covariance has every correlation: 60 steps at changing
// attitudes and specific forces, then one velocity update.
Ekf15 correlated_filter(const Ekf15::Noise& q) {
    Ekf15 ekf;
    double d[15];
    for (int i = 0; i < 15; ++i) d[i] = 0.01 * (i + 1);
    ekf.reset_covariance(d);
    for (int k = 0; k < 60; ++k)
        ekf.propagate(0.005, attitude(0.05 * k, 0.3 * std::sin(0.2 * k), -0.2), Vec3(3.0 * std::cos(0.3 * k), -2.0, 9.81), q);
    const double z[3] = {0.01, -0.02, 0.0}, var[3] = {1e-4, 1e-4, 1e-4};
    ekf.update_block3(Ekf15::VEL, z, var);
    return ekf;
}

MatN covariance_of(const Ekf15& e) {
    MatN P;
    for (int i = 0; i < 15; ++i)
        for (int j = 0; j < 15; ++j) P(i, j) = e.P(i, j);
    return P;
}
}  // namespace

TEST_CASE("skew matrix is the cross product (foot-imu-zupt-zaru-ekf eq. (9) as corrected)") {
    const Vec3 w(0.3, -1.2, 2.5), v(-0.7, 0.4, 1.1);
    CHECK((skew(w) * v - w.cross(v)).norm() < 1e-15);
    CHECK((skew(w) + skew(w).transpose()).norm() == 0.0);
}

TEST_CASE("Cayley transform is a rotation and matches the exponential to second order") {
    for (double a : {1e-3, 1e-2, 0.1}) {
        const Vec3 r = a * Vec3(0.3, -0.5, 0.8).normalized();
        const Mat3 c = cayley(r);
        CHECK((c * c.transpose() - Mat3::Identity()).norm() < 1e-14);
        const Mat3 e = quat_exp(r).toRotationMatrix();
        // The Pade (1,1) error is (|r|^3)/12.
        CHECK((c - e).norm() < a * a * a / 6.0 + 1e-15);
    }
}

TEST_CASE("quaternion exp and log are inverse, also near zero") {
    for (double a : {0.0, 1e-9, 1e-4, 0.5, 3.0}) {
        const Vec3 r = a * Vec3(-0.2, 0.9, 0.4).normalized();
        CHECK((quat_log(quat_exp(r)) - r).norm() < 1e-12);
        CHECK(std::abs(quat_exp(r).norm() - 1.0) < 1e-15);
    }
}

TEST_CASE("renormalize brings a product of unit quaternions back to unit length, and far-off ones exactly") {
    Quat q(0.3, -0.5, 0.7, 0.2);
    q.normalize();
    Quat near = q;
    near.coeffs() *= 1.0 + 3e-9;  // |q|^2 = 1 + 6e-9
    renormalize(near);
    CHECK(std::abs(near.squaredNorm() - 1.0) < 4e-16);
    CHECK(near.angularDistance(q) < 1e-15);
    Quat far(2.0, 0.0, 0.0, 0.0);
    renormalize(far);
    CHECK(far.w() == 1.0);
    Quat zero(0.0, 0.0, 0.0, 0.0);
    renormalize(zero);
    CHECK(zero.coeffs().cwiseAbs().maxCoeff() == 0.0);
    CHECK(unit_length_scale(std::nan("")) == 1.0);
}

TEST_CASE("rotate(q, v) is q.toRotationMatrix() * v bit for bit") {
    std::mt19937 rng(11);
    std::normal_distribution<double> n01(0.0, 1.0);
    int differ = 0;
    for (int k = 0; k < 1000; ++k) {
        const Quat q = Quat(n01(rng), n01(rng), n01(rng), n01(rng)).normalized();
        const Vec3 v(10 * n01(rng), 10 * n01(rng), 10 * n01(rng));
        const Mat3 R = q.toRotationMatrix();
        const Vec3 ref = R * v;
        differ += rotate(q, v) != ref;
    }
    CHECK(differ == 0);
}

TEST_CASE("quat_mul_unit is the Hamilton product at unit length, in either order, also from off-unit factors") {
    std::mt19937 rng(7);
    std::normal_distribution<double> n01(0.0, 1.0);
    double worst_product = 0, worst_norm = 0;
    for (int k = 0; k < 1000; ++k) {
        const Quat a = Quat(n01(rng), n01(rng), n01(rng), n01(rng)).normalized();
        const Quat b = quat_exp(0.01 * Vec3(n01(rng), n01(rng), n01(rng)));
        for (const auto& [l, r] : {std::pair<Quat, Quat>{a, b}, std::pair<Quat, Quat>{b, a}}) {
            const Quat ref = (l * r).normalized();
            const Quat got = quat_mul_unit(l, r);
            worst_product = std::max(worst_product, (got.coeffs() - ref.coeffs()).cwiseAbs().maxCoeff());
            worst_norm = std::max(worst_norm, std::abs(got.squaredNorm() - 1.0));
        }
    }
    CHECK(worst_product < 1e-15);
    CHECK(worst_norm < 1e-15);
    // Far from unit length: normalized exactly.
    const Quat big = quat_mul_unit(Quat(2.0, 0.0, 0.0, 0.0), Quat(0.0, 0.0, 3.0, 0.0));
    CHECK(big.y() == 1.0);
    CHECK(big.w() == 0.0);
    // A zero product stays zero (no division by its norm).
    const Quat zero = quat_mul_unit(Quat(0.0, 0.0, 0.0, 0.0), Quat(0.6, 0.0, 0.8, 0.0));
    CHECK(zero.coeffs().cwiseAbs().maxCoeff() == 0.0);
}

TEST_CASE("atan2_fast agrees with libm's atan2 to about an ulp in every octant") {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    double max_err = 0.0;
    for (int i = 0; i < 200000; ++i) {
        double y = u(rng), x = u(rng);
        if (i % 3 == 0) y *= 1e-4;
        if (i % 5 == 0) x *= 1e-7;
        max_err = std::max(max_err, std::abs(atan2_fast(y, x) - std::atan2(y, x)));
    }
    CHECK(max_err < 1e-15);
    for (double y : {0.0, -0.0, 1.0, -1.0})
        for (double x : {0.0, -0.0, 1.0, -1.0}) CHECK(atan2_fast(y, x) == std::atan2(y, x));
    CHECK(atan2_fast(1.0, 1.0) == std::atan2(1.0, 1.0));
    CHECK(std::isnan(atan2_fast(NAN, 1.0)));
}

TEST_CASE("level alignment and tilt-compensated magnetometer heading at several attitudes") {
    const double g = 9.81;
    const double dip = 64 * kDeg, field = 48.0;
    const Vec3 m_enu(0.0, field * std::cos(dip), -field * std::sin(dip));  // magnetic north, pointing down
    for (double heading : {0.0, 37.0, 135.0, -100.0, 179.0})
        // 75-83 deg: body x tilted 7-15 deg off vertical, still heading_of()'s x axis
        // case; -87 deg: within 6 deg of vertical, the y axis case.
        for (double pitch : {0.0, 20.0, -35.0, 60.0, 75.0, 80.0, 83.0, -87.0})
            for (double roll : {0.0, 25.0, -50.0, 170.0}) {  // 170 deg: the sensor upside down (z down)
                const Mat3 R = attitude(heading * kDeg, pitch * kDeg, roll * kDeg);
                const Vec3 f_body = R.transpose() * Vec3(0, 0, g);
                const Vec3 m_body = R.transpose() * m_enu;
                const Quat q(R);
                const double psi_true = heading_of(q);
                CHECK(std::abs(wrap_pi(magnetic_heading(f_body, m_body) - psi_true)) < 1e-9);
                const Quat qa = level_attitude(f_body, psi_true);
                CHECK(std::abs(wrap_pi(heading_of(qa) - psi_true)) < 1e-9);
                CHECK((qa.toRotationMatrix() - R).norm() < 1e-9);
            }
}

TEST_CASE("strapdown aligns on the still period and takes the heading from a trusted magnetometer") {
    StrapdownConfig c;
    c.declination_deg = 2.0;
    Strapdown sd(c);
    const Mat3 R = attitude(70 * kDeg, 15 * kDeg, -40 * kDeg);
    const Vec3 f = R.transpose() * Vec3(0, 0, 9.6);  // a sensor reading 0.98 g
    const Vec3 bias(0.01, -0.02, 0.005);
    const Vec3 m = R.transpose() * Vec3(0, 20.0, -40.0);
    bool aligned = false;
    int64_t t = 0;
    for (int k = 0; k < 300 && !aligned; ++k, t += 5000000) {
        sd.on_mag(t, m);
        aligned = sd.on_imu(t, f, bias);
    }
    REQUIRE(aligned);
    CHECK(sd.heading_from_magnetometer());
    CHECK(std::abs(wrap_pi(heading_of(sd.q()) - (70 + 2) * kDeg)) < 1e-6);
    CHECK((sd.gyro_bias() - bias).norm() < 1e-12);
    // Field strength outside the trusted band: heading from the parameter.
    StrapdownConfig c2;
    c2.initial_heading_deg = -30.0;
    Strapdown sd2(c2);
    aligned = false;
    t = 0;
    for (int k = 0; k < 300 && !aligned; ++k, t += 5000000) {
        sd2.on_mag(t, m * 0.01);
        aligned = sd2.on_imu(t, f, bias);
    }
    REQUIRE(aligned);
    CHECK_FALSE(sd2.heading_from_magnetometer());
    CHECK(std::abs(wrap_pi(heading_of(sd2.q()) + 30 * kDeg)) < 1e-6);
}

TEST_CASE("attitude integration with mid-interval rates and coning is exact for a coning motion") {
    // Classic coning: the body rotates about a cone; the exact attitude is known.
    const double rate = 400.0, dt = 1.0 / rate;
    const double cone = 0.3, spin = 2 * M_PI * 2.0;  // half-angle (rad), cone frequency (rad/s)
    auto q_true = [&](double t) {
        // q(t) = exp(cone * [cos(spin t), sin(spin t), 0]) about a rotating axis, relative to the start.
        return quat_exp(cone * Vec3(std::cos(spin * t), std::sin(spin * t), 0.0));
    };
    auto body_rate = [&](double t) {
        // Numerical body rate from the exact attitude: w = 2 Im(q^-1 dq/dt).
        const double h = 1e-6;
        const Quat d = q_true(t).conjugate() * q_true(t + h);
        const Quat d0 = q_true(t - h).conjugate() * q_true(t);
        return Vec3((quat_log(d) + quat_log(d0)) / (2 * h));
    };
    StrapdownConfig c;
    Strapdown sd(c);
    sd.set_attitude(q_true(0.0));
    const Vec3 f(0, 0, 9.81);
    int64_t t_ns = 0;
    sd.on_imu(t_ns, f, body_rate(0.0));
    for (int k = 1; k <= static_cast<int>(2.0 * rate); ++k) {
        t_ns = static_cast<int64_t>(std::llround(k * dt * 1e9));
        sd.on_imu(t_ns, f, body_rate(k * dt));
    }
    const double err = quat_log(sd.q().conjugate() * q_true(2.0)).norm();
    // Two seconds of 0.3 rad coning at 2 Hz (peak rate 3.8 rad/s): drift below 0.05 deg.
    CHECK(err < 0.05 * kDeg);
}

TEST_CASE("EKF propagation matches the dense Phi P Phi^T + Q, and the Joseph update the textbook one") {
    Ekf15 ekf;
    double d[15];
    for (int i = 0; i < 15; ++i) d[i] = 0.01 * (i + 1);
    ekf.reset_covariance(d);
    Ekf15::Noise q{1e-4, 1e-3, 1e-8, 1e-6};
    const Mat3 R = attitude(0.4, 0.3, -0.2);
    const Vec3 f(1.0, -2.0, 9.81);
    const double dt = 0.005;
    for (int k = 0; k < 200; ++k) ekf.propagate(dt, R, f, q);
    // One more step against the dense reference.
    const MatN P0 = covariance_of(ekf), Phi = dense_transition(dt, R, f);
    const MatN P1_ref = Phi * P0 * Phi.transpose() + dense_noise(dt, q);
    ekf.propagate(dt, R, f, q);
    double max_prop_diff = 0;
    for (int i = 0; i < 15; ++i)
        for (int j = 0; j < 15; ++j) max_prop_diff = std::max(max_prop_diff, std::abs(ekf.P(i, j) - P1_ref(i, j)));
    CHECK(max_prop_diff < 1e-12);
    // Textbook update for H = e_9 on a copy.
    const MatN P = covariance_of(ekf);
    const double r = 1e-4;
    const Eigen::Matrix<double, 15, 1> K = P.col(9) / (P(9, 9) + r);
    const Eigen::Matrix<double, 15, 15> P_ref = P - K * P.row(9);
    ekf.update_scalar(9, 0.1, r);
    double max_diff = 0;
    for (int i = 0; i < 15; ++i)
        for (int j = 0; j < 15; ++j) max_diff = std::max(max_diff, std::abs(ekf.P(i, j) - P_ref(i, j)));
    CHECK(max_diff < 1e-12);
    CHECK(std::abs(ekf.x()[9] - K(9) * 0.1) < 1e-15);
    // Positive semi-definite.
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 15, 15>> es(P_ref);
    CHECK(es.eigenvalues().minCoeff() > -1e-12);
}

// ---------------------------------------------------------------- detectors

namespace {
struct Synthetic {
    std::vector<int64_t> t_ns;
    std::vector<Vec3> a, w;
    std::vector<int> stance;
};

// Walking or running: stance (foot flat, gravity at `g_read` along a tilted
// axis, plus the small roll of a real foot) then swing (large rotation and
// acceleration), with white noise.
Synthetic gait(double rate_hz, double stance_s, double swing_s, double g_read, int cycles, double roll_rate,
               double swing_scale, uint32_t seed) {
    Synthetic s;
    std::mt19937 rng(seed);
    std::normal_distribution<double> n01(0.0, 1.0);
    const Vec3 up = Vec3(0.5, 0.2, -0.84).normalized();  // tilted, z down
    const double period = stance_s + swing_s;
    const int n = static_cast<int>((0.8 + cycles * period + 0.5 * stance_s) * rate_hz);  // ends mid-stance
    for (int k = 0; k < n; ++k) {
        const double t = k / rate_hz;
        const double tc = t < 0.8 ? -1.0 : std::fmod(t - 0.8, period);
        const bool st = tc < 0 || tc < stance_s;
        Vec3 a = g_read * up, w = Vec3::Zero();
        if (!st) {
            const double ph = (tc - stance_s) / swing_s;  // 0..1
            const double env = std::sin(M_PI * ph);
            w = swing_scale * env * Vec3(1.0, 5.0 * std::sin(2 * M_PI * ph), 0.8);
            a += swing_scale * env * Vec3(12.0 * std::sin(2 * M_PI * ph), 3.0, 8.0 * std::cos(2 * M_PI * ph));
        } else if (tc >= 0) {
            w = roll_rate * std::sin(M_PI * tc / stance_s) * Vec3(0.0, 1.0, 0.2);  // heel-to-toe roll
        }
        a += 0.05 * Vec3(n01(rng), n01(rng), n01(rng));
        w += 0.01 * Vec3(n01(rng), n01(rng), n01(rng));
        s.t_ns.push_back(static_cast<int64_t>(std::llround(t * 1e9)));
        s.a.push_back(a);
        s.w.push_back(w);
        s.stance.push_back(st ? 1 : 0);
    }
    return s;
}

int segments_of(const std::vector<int>& stance) {
    int n = 0, prev = 0;
    for (int s : stance) {
        n += s && !prev;
        prev = s;
    }
    return n;
}

struct DetectionScore {
    int segments = 0;
    double agreement = 0;  // share of samples whose decision equals the truth
    bool latency_kept = true;
    size_t outputs = 0;
};

DetectionScore detect(StanceDetector& d, const Synthetic& s) {
    std::vector<StanceDecision> out;
    DetectionScore sc;
    for (size_t k = 0; k < s.t_ns.size(); ++k) {
        const size_t before = out.size();
        d.push(s.t_ns[k], s.a[k].data(), s.w[k].data(), [&](const StanceDecision& x) { out.push_back(x); });
        // Every decision about t is out once input t + latency is in, not later.
        for (size_t j = before; j < out.size(); ++j)
            if (k > 0 && s.t_ns[k - 1] >= out[j].t_ns + d.latency_ns()) sc.latency_kept = false;
        const size_t due = static_cast<size_t>(
            std::upper_bound(s.t_ns.begin(), s.t_ns.end(), s.t_ns[k] - d.latency_ns()) - s.t_ns.begin());
        if (out.size() < due) sc.latency_kept = false;
    }
    d.flush([&](const StanceDecision& x) { out.push_back(x); });
    sc.outputs = out.size();
    int agree = 0, prev = 0;
    for (size_t k = 0; k < out.size() && k < s.t_ns.size(); ++k) {
        REQUIRE(out[k].t_ns == s.t_ns[k]);
        agree += (out[k].stance ? 1 : 0) == s.stance[k];
        if (out[k].stance && !prev) ++sc.segments;
        prev = out[k].stance;
    }
    sc.agreement = static_cast<double>(agree) / s.t_ns.size();
    return sc;
}
}  // namespace

TEST_CASE("stance detectors give the same decisions at 100, 200, 250 and 400 Hz on a 0.97 g sensor") {
    for (double rate : {100.0, 200.0, 250.0, 400.0}) {
        CAPTURE(rate);
        const Synthetic walk = gait(rate, 0.35, 0.65, 0.97 * 9.80665, 12, 0.3, 1.0, 7);
        MultiConditionConfig mc;
        StanceDetector multi(mc, 1000.0);
        const DetectionScore a = detect(multi, walk);
        CHECK(a.outputs == walk.t_ns.size());
        CHECK(a.latency_kept);
        const int truth = segments_of(walk.stance);
        CHECK(truth == 13);  // the opening still period runs into the first stance
        CHECK(a.segments == truth);
        CHECK(a.agreement > 0.9);
        ShoeConfig sc;
        StanceDetector shoe(sc, 1000.0);
        const DetectionScore b = detect(shoe, walk);
        CHECK(b.outputs == walk.t_ns.size());
        CHECK(b.latency_kept);
        CHECK(b.segments == truth);
        CHECK(b.agreement > 0.9);
    }
}

TEST_CASE("running: the adaptive SHOE detector finds every brief, rolling stance") {
    for (double rate : {100.0, 200.0, 400.0}) {
        CAPTURE(rate);
        // 0.12 s stances with a 1.2 rad/s heel-to-toe roll, violent swings.
        const Synthetic run = gait(rate, 0.12, 0.55, 9.80665, 15, 1.2, 2.5, 11);
        ShoeConfig sc;
        StanceDetector shoe(sc, 1000.0);
        const DetectionScore b = detect(shoe, run);
        CHECK(b.latency_kept);
        const int truth = segments_of(run.stance);
        CHECK(b.segments == truth);
        // The paper's detector with its printed thresholds misses them (|w| > 1 rad/s).
        MultiConditionConfig mc;
        StanceDetector multi(mc, 1000.0);
        CHECK(detect(multi, run).segments < truth);
    }
}

TEST_CASE("SHOE statistic equals the direct sum over its window, with g given and with the window's |mean a|") {
    // 200 Hz walk on a sensor reading 0.97 g at rest. The detector keeps
    // running sums; the reference sums the window anew for every sample:
    // T = 1/n sum_j (|a_j - g u|^2 / sigma_a^2 + |w_j|^2 / sigma_w^2), u = mean a / |mean a|.
    const double g_read = 0.97 * 9.80665;
    const Synthetic walk = gait(200.0, 0.35, 0.65, g_read, 6, 0.3, 1.0, 5);
    double mean_still_given = 0, mean_still_own = 0;
    const ShoeConfig sc_default;
    for (double g : {0.0, 9.80665, 9.5}) {
        CAPTURE(g);
        ShoeConfig sc;
        sc.adaptive_window_s = 0.0;
        sc.gravity_mps2 = g;
        StanceDetector shoe(sc, 1000.0);
        std::vector<StanceDecision> out;
        const auto keep = [&](const StanceDecision& x) { out.push_back(x); };
        for (size_t k = 0; k < walk.t_ns.size(); ++k) shoe.push(walk.t_ns[k], walk.a[k].data(), walk.w[k].data(), keep);
        shoe.flush(keep);
        REQUIRE(out.size() == walk.t_ns.size());
        const int64_t h = static_cast<int64_t>(std::llround(sc.window_s * 0.5e9));
        double worst = 0, still_sum = 0;
        int compared = 0, still_n = 0;
        for (size_t k = 0; k < out.size(); ++k) {
            const int64_t t = walk.t_ns[k];
            if (t - h < walk.t_ns.front() || t + h > walk.t_ns.back()) continue;  // truncated windows
            Vec3 sum_a = Vec3::Zero();
            std::vector<size_t> in;
            for (size_t j = 0; j < walk.t_ns.size(); ++j)
                if (walk.t_ns[j] >= t - h && walk.t_ns[j] <= t + h) {
                    in.push_back(j);
                    sum_a += walk.a[j];
                }
            const double n = static_cast<double>(in.size());
            const Vec3 u = sum_a.normalized();
            const double gw = g > 0 ? g : sum_a.norm() / n;
            double T = 0;
            for (size_t j : in)
                T += (walk.a[j] - gw * u).squaredNorm() / (sc.accel_sd_mps2 * sc.accel_sd_mps2) +
                     walk.w[j].squaredNorm() / (sc.gyro_sd_radps * sc.gyro_sd_radps);
            T /= n;
            worst = std::max(worst, std::abs(out[k].statistic - T) / std::max(1.0, T));
            ++compared;
            if (t < 700000000) {  // the opening still period
                still_sum += T;
                ++still_n;
            }
        }
        CHECK(compared > 1000);
        CHECK(worst < 1e-9);
        if (g == 0.0) mean_still_own = still_sum / still_n;
        if (g == 9.80665) mean_still_given = still_sum / still_n;
    }
    // At rest the window's own |mean a| removes the 3 % scale error; a given
    // g leaves (0.03 g)^2 / sigma_a^2 in T (0.087 with sigma_a 1 m/s^2).
    CHECK(mean_still_own < 0.02);
    CHECK(mean_still_given - mean_still_own ==
          doctest::Approx(std::pow(g_read - 9.80665, 2) / (sc_default.accel_sd_mps2 * sc_default.accel_sd_mps2))
              .epsilon(0.05));
}

TEST_CASE("stance detector windows are in seconds: latency does not depend on the rate") {
    MultiConditionConfig mc;
    mc.window_s = 0.2;
    mc.median_window_s = 0.1;
    mc.adaptive_window_s = 0.0;
    StanceDetector a(mc, 100.0), b(mc, 400.0);
    CHECK(a.latency_ns() == 150000000);
    CHECK(b.latency_ns() == 150000000);
    mc.adaptive_window_s = 1.0;
    StanceDetector c(mc, 250.0);
    CHECK(c.latency_ns() == 650000000);
    ShoeConfig sc;
    StanceDetector s(sc, 250.0);
    CHECK(s.latency_ns() == static_cast<int64_t>(std::llround((sc.window_s + sc.adaptive_window_s + sc.median_window_s) * 0.5e9)));
}

TEST_CASE("EKF block update of three selected states equals three scalar updates") {
    Ekf15 a, b;
    double d[15];
    for (int i = 0; i < 15; ++i) d[i] = 0.02 * (i + 1);
    a.reset_covariance(d);
    Ekf15::Noise q{1e-4, 1e-3, 1e-8, 1e-6};
    const Mat3 R = attitude(1.1, -0.2, 0.4);
    for (int k = 0; k < 100; ++k) a.propagate(0.01, R, Vec3(2.0, 1.0, 9.0), q);
    b = a;
    const double z[3] = {0.1, -0.05, 0.02}, var[3] = {1e-4, 2e-4, 3e-4};
    a.update_block3(Ekf15::VEL, z, var);
    for (int i = 0; i < 3; ++i) b.update_scalar(Ekf15::VEL + i, z[i], var[i]);
    double dp = 0, dx = 0;
    for (int i = 0; i < 15; ++i) {
        dx = std::max(dx, std::abs(a.x()[i] - b.x()[i]));
        for (int j = 0; j < 15; ++j) {
            dp = std::max(dp, std::abs(a.P(i, j) - b.P(i, j)));
        }
    }
    CHECK(dx < 1e-12);
    CHECK(dp < 1e-12);
}

TEST_CASE("level memory: a floor reached again gets its first height back, a new one is remembered") {
    LevelMemory m(0.1);
    CHECK(m.arrive(0.0) == 0.0);   // start floor
    CHECK(m.arrive(1.52) == 1.52); // landing: new
    CHECK(m.arrive(3.05) == 3.05); // floor 1: new
    CHECK(m.size() == 3);
    CHECK(m.arrive(1.58) == 1.52); // the landing again, 6 cm off
    CHECK(m.arrive(-0.07) == 0.0); // the start floor again
    CHECK(m.arrive(0.17) == 0.17); // one riser above the start floor: another level
    CHECK(m.arrive(0.09) == 0.17); // nearest of the two within reach
    CHECK(m.size() == 4);
    LevelMemory off(0.0);
    CHECK(off.arrive(1.0) == 1.0);
    CHECK(off.arrive(1.0) == 1.0);
    CHECK(off.size() == 0);
}

TEST_CASE("ZUPT on a rolling foot expects the sensor's velocity about the contact point") {
    // The sensor sits tilted and yawed on the foot (R = ENU from body). The
    // foot first moves (velocity about 0.24 m/s east, 0.12 m/s north), then
    // stands on the ground and pitches at 2 rad/s about the ENU north axis
    // through its contact point; the sensor, 0.08 m above the sole, then
    // moves at h (w_n, -w_e, 0) = (0.16, 0, 0) m/s, east. With height 0 (the
    // plain ZUPT) the velocity goes to zero.
    const Mat3 R = attitude(1.1, 0.4, -0.3);
    const Quat q(R);
    const Vec3 w_enu(0.0, 2.0, 0.0), g_enu(0.0, 0.0, 9.80665), push_enu(2.0, 1.0, 0.0);
    const Vec3 w_body = R.transpose() * w_enu;
    for (double height : {0.0, 0.08}) {
        FootInsConfig c;
        c.sensor_height_m = height;
        c.zupt_lever_m = 0.0;
        c.zaru = false;
        c.hupt = false;
        c.gravity_mps2 = 9.80665;
        FootIns ins(c);
        ins.set_start(Vec3::Zero(), NAN);
        SampleOut out;
        int64_t t = 0;
        for (int k = 0; k < 24; ++k, t += 5'000'000LL)  // 0.12 s of push: v = (0.24, 0.12, 0)
            ins.step(t, R.transpose() * (g_enu + (k > 0 ? push_enu : Vec3::Zero())), Vec3::Zero(), q, Vec3::Zero(),
                     false, out);
        CHECK(out.vel.x() > 0.2);
        for (int k = 0; k < 40; ++k, t += 5'000'000LL)
            ins.step(t, R.transpose() * g_enu, w_body, q, Vec3::Zero(), true, out);
        CAPTURE(height);
        CAPTURE(out.vel.transpose());
        CHECK(std::abs(out.vel.x() - height * w_enu.y()) < 1e-3);
        CHECK(std::abs(out.vel.y() + height * w_enu.x()) < 1e-3);
        CHECK(std::abs(out.vel.z()) < 1e-3);
    }
}

namespace {
// Strides of a foot that stands 1 s, then twice swings 0.7 m east (0.5 s,
// a = A sin(2 pi t / T), back to rest) and stands 0.5 s; the accelerometer
// reads accel_scale times the truth (a level sensor, no rotation).
std::vector<double> stride_lengths_m(const FootInsConfig& c, double accel_scale, bool zero_first_sample = false) {
    const double dt = 0.005, T = 0.5, A = 0.7 * 2.0 * M_PI / (T * T), g = 9.80665;
    FootIns ins(c);
    ins.set_start(Vec3::Zero(), NAN);
    SampleOut out;
    std::vector<double> strides;
    int64_t t_ns = 0;
    bool finite = true;
    const auto sample = [&](double ax, bool stance) {
        const Vec3 a = accel_scale * Vec3(ax, 0.0, g);
        ins.step(t_ns, zero_first_sample && t_ns == 0 ? Vec3::Zero() : a, Vec3::Zero(), Quat::Identity(),
                 Vec3::Zero(), stance, out);
        if (out.stride) strides.push_back(ins.stride_out().displacement.x());
        finite = finite && std::isfinite(out.pos.sum()) && std::isfinite(out.vel.sum());
        t_ns += 5'000'000;
    };
    for (int k = 0; k < 200; ++k) sample(0.0, true);
    for (int step = 0; step < 2; ++step) {
        for (int k = 1; k < 100; ++k) sample(A * std::sin(2.0 * M_PI * k * dt / T), false);
        for (int k = 0; k < 100; ++k) sample(0.0, true);
    }
    StrideOut last;
    if (ins.finish(last)) strides.push_back(last.displacement.x());
    if (!finite) strides.clear();
    return strides;
}
}  // namespace

TEST_CASE("accelerometer rescale: a sensor that reads off gravity at rest gets its strides back when asked") {
    FootInsConfig c;
    c.hupt = false;
    const auto check_strides = [](const std::vector<double>& s, double expect_m) {
        REQUIRE(s.size() == 2);
        for (double d : s) CHECK(d == doctest::Approx(expect_m).epsilon(0.003));
    };
    // As read (the preset): every stride as long as the scale error makes it.
    check_strides(stride_lengths_m(c, 1.047), 0.7 * 1.047);
    check_strides(stride_lengths_m(c, 0.97), 0.7 * 0.97);
    // Rescaled above 2 %: the 4.7 % and -3 % sensors, not the 1 % one.
    c.accel_rescale_above = 0.02;
    check_strides(stride_lengths_m(c, 1.047), 0.7);
    check_strides(stride_lengths_m(c, 0.97), 0.7);
    check_strides(stride_lengths_m(c, 1.01), 0.7 * 1.01);
    c.accel_rescale_above = 0.0;
    check_strides(stride_lengths_m(c, 1.01), 0.7);
    // Local gravity other than the standard one: a sensor reading 9.80665 at
    // the equator (9.78) reads 0.27 % high.
    c.local_gravity_mps2 = 9.78;
    check_strides(stride_lengths_m(c, 1.0), 0.7 * 9.78 / 9.80665);
    // A first stance that starts with a zero reading (a logger's dropout):
    // no division by it, every output finite.
    c.local_gravity_mps2 = 9.80665;
    c.accel_rescale_above = 0.02;
    CHECK(stride_lengths_m(c, 1.0, true).size() == 2);
}

TEST_CASE("EKF block update that holds some states equals the textbook Joseph form with those gain rows zero") {
    const Ekf15::Noise q{1e-4, 1e-3, 1e-8, 1e-6};
    Ekf15 ekf = correlated_filter(q);
    ekf.clear_state();
    const MatN P = covariance_of(ekf);
    const double z[3] = {0.003, -0.002, 0.001}, var[3] = {4e-4, 4e-4, 4e-4};
    const uint32_t hold = 7u << Ekf15::POS;
    // Textbook: K = P H^T S^-1 with the held rows zeroed, Joseph form.
    Eigen::Matrix<double, 3, 15> H = Eigen::Matrix<double, 3, 15>::Zero();
    for (int j = 0; j < 3; ++j) H(j, Ekf15::BG + j) = 1.0;
    const Mat3 S = H * P * H.transpose() + Mat3(Vec3(var[0], var[1], var[2]).asDiagonal());
    Eigen::Matrix<double, 15, 3> K = P * H.transpose() * S.inverse();
    K.middleRows<3>(Ekf15::POS).setZero();
    const MatN IKH = MatN::Identity() - K * H;
    const MatN P_ref = IKH * P * IKH.transpose() + K * Mat3(Vec3(var[0], var[1], var[2]).asDiagonal()) * K.transpose();
    const Eigen::Matrix<double, 15, 1> x_ref = K * Vec3(z[0], z[1], z[2]);
    for (bool joseph : {true, false}) {  // a held state always takes the Joseph form
        CAPTURE(joseph);
        Ekf15 e = ekf;
        e.set_joseph(joseph);
        e.update_block3(Ekf15::BG, z, var, hold);
        double dp = 0, dx = 0;
        for (int i = 0; i < 15; ++i) {
            dx = std::max(dx, std::abs(e.x()[i] - x_ref(i)));
            for (int j = 0; j < 15; ++j) dp = std::max(dp, std::abs(e.P(i, j) - P_ref(i, j)));
        }
        CHECK(dp < 1e-14);
        CHECK(dx < 1e-16);
        for (int i = 0; i < 3; ++i) CHECK(e.x()[Ekf15::POS + i] == 0.0);
    }
    // Holding costs information: the held update leaves more variance than the optimal one.
    Ekf15 opt = ekf;
    opt.update_block3(Ekf15::BG, z, var);
    Ekf15 held = ekf;
    held.update_block3(Ekf15::BG, z, var, hold);
    for (int i = 0; i < 15; ++i) CHECK(held.P(i, i) >= opt.P(i, i) - 1e-15);
    CHECK(held.P(Ekf15::POS, Ekf15::POS) > opt.P(Ekf15::POS, Ekf15::POS));
}

TEST_CASE("EKF deferred swing propagation: the structured product equals the dense one, noise split at both ends") {
    const auto max_abs = [](const MatN& m) { return m.cwiseAbs().maxCoeff(); };
    const Ekf15::Noise q{1e-4, 1e-3, 1e-8, 1e-6};
    Ekf15 ekf = correlated_filter(q);
    const MatN P0 = covariance_of(ekf);

    // A swing: 24 intervals of uneven length, the foot pitching through 100
    // degrees and turning, specific force up to 3 g.
    MatN M = MatN::Identity(), Qsum = MatN::Zero(), P_each = P0;
    Ekf15 per_step = ekf;
    double t_s = 0;
    for (int k = 0; k < 24; ++k) {
        const double dt = 0.004 + 0.001 * (k % 3);
        const Mat3 R = attitude(0.4 + 0.02 * k, -0.8 + 0.075 * k, 0.1 * std::sin(0.5 * k));
        const Vec3 f(25.0 * std::sin(0.3 * k), 4.0 * std::cos(0.7 * k), 9.81 + 15.0 * std::cos(0.25 * k));
        const MatN Phi = dense_transition(dt, R, f), Q = dense_noise(dt, q);
        M = Phi * M;
        Qsum += Q;
        P_each = Phi * P_each * Phi.transpose() + Q;
        ekf.defer_propagation(dt, R, f, q);
        per_step.propagate(dt, R, f, q);
        t_s += dt;
    }
    CHECK(ekf.deferred_s() == doctest::Approx(t_s).epsilon(1e-12));
    // Until applied, P is the covariance before the swing.
    CHECK(max_abs(covariance_of(ekf) - P0) == 0.0);

    // The updates and propagate() apply the deferred transition first;
    // reset_covariance() drops it.
    Ekf15 updated = ekf, block_updated = ekf, propagated = ekf, reset = ekf;
    ekf.apply_deferred();
    CHECK(ekf.deferred_s() == 0.0);
    const MatN P_def = covariance_of(ekf);
    const MatN P_ref = M * (P0 + 0.5 * Qsum) * M.transpose() + 0.5 * Qsum;
    CHECK(max_abs(P_def - P_ref) < 1e-12 * max_abs(P_ref));
    CHECK(max_abs(P_def - P_def.transpose()) == 0.0);

    // Against propagating every interval: the one product is exact but for
    // where the noise enters; half at each end is closer than all at the end.
    CHECK(max_abs(covariance_of(per_step) - P_each) < 1e-12 * max_abs(P_each));
    // Errors relative to the noise's share of the swing's covariance (this
    // swing of 0.12 s, a little longer than the preset interval, at up to
    // 3 g: 4.6 % and 10 %; the rest of the covariance is exact).
    const MatN noise_part = P_each - M * P0 * M.transpose();
    const MatN P_end = M * P0 * M.transpose() + Qsum;
    const double err_split = (P_def - P_each).norm() / noise_part.norm();
    const double err_end = (P_end - P_each).norm() / noise_part.norm();
    MESSAGE("deferred vs every interval, relative to the noise's share: noise split " << err_split
            << ", noise at the end " << err_end);
    CHECK(err_split < 0.06);
    CHECK(err_split < 0.6 * err_end);

    const auto same = [&](const Ekf15& a, const Ekf15& b) {
        CHECK(a.deferred_s() == 0.0);
        CHECK(max_abs(covariance_of(a) - covariance_of(b)) == 0.0);
        for (int i = 0; i < 15; ++i) CHECK(a.x()[i] == b.x()[i]);
    };
    Ekf15 applied = ekf;
    const double zv = 0.05;
    updated.update_scalar(Ekf15::VEL, zv, 1e-4);
    applied.update_scalar(Ekf15::VEL, zv, 1e-4);
    same(updated, applied);
    const double z3[3] = {0.02, -0.01, 0.005}, var3[3] = {1e-4, 2e-4, 3e-4};
    applied = ekf;
    block_updated.update_block3(Ekf15::BG, z3, var3);
    applied.update_block3(Ekf15::BG, z3, var3);
    same(block_updated, applied);
    applied = ekf;
    const Mat3 R1 = attitude(0.9, 0.1, 0.05);
    const Vec3 f1(0.3, -0.2, 9.8);
    propagated.propagate(0.005, R1, f1, q);
    applied.propagate(0.005, R1, f1, q);
    same(propagated, applied);
    double d[15];
    for (int i = 0; i < 15; ++i) d[i] = 0.02 * (i + 1);
    Ekf15 fresh;
    fresh.reset_covariance(d);
    reset.reset_covariance(d);
    reset.propagate(0.005, R1, f1, q);
    fresh.propagate(0.005, R1, f1, q);
    same(reset, fresh);
}
