/* SPDX-License-Identifier: Apache-2.0 */
/*
 * pednav stable C ABI, part 1 of 3: status codes, the error struct, and the
 * time-stamped records that flow between the engine, its plugins and the app.
 *
 * C99, depends only on <stdint.h>. Frozen per ABI major: minors only append
 * (new record types, new fields at the tail of a record, new status codes).
 *
 * Conventions (one set for the whole engine, see docs/conventions.md):
 *   - navigation frame: East-North-Up (ENU) metres; its origin is the engine's
 *     geodetic origin (pn_geo_point_t) once it has one, else the start point;
 *   - body frame: Forward-Left-Up (FLU), the IMU's own axes after the reader's
 *     axis remap; nothing assumes the sensor sits level;
 *   - SI units, written in every field name: s, m, m/s, m/s^2, rad, rad/s,
 *     microtesla (ut), pascal (pa);
 *   - quaternions are Hamilton, w first; the name says the direction
 *     (q_enu_from_body rotates a body-frame vector into ENU);
 *   - heading is clockwise from north (azimuth) in radians unless named _deg;
 *   - 3x3 covariances are row-major;
 *   - time is one monotonic clock in nanoseconds (t_ns); never wall clock. Inputs
 *     must lie within +-2^62 ns of zero (PN_E_INVALID_ARGUMENT otherwise).
 */
#ifndef PEDNAV_PN_TYPES_H
#define PEDNAV_PN_TYPES_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define PN_ABI_MAJOR 1
#define PN_ABI_MINOR 1
/* abi_version field value: major in the high 16 bits, minor in the low 16. */
#define PN_ABI_VERSION ((uint32_t)((PN_ABI_MAJOR << 16) | PN_ABI_MINOR))
#define PN_ABI_VERSION_MAJOR(v) ((uint32_t)(v) >> 16)
#define PN_ABI_VERSION_MINOR(v) ((uint32_t)(v)&0xffffu)

/* ---------------------------------------------------------------- status */

/* 0 = success, >0 = success with a note, <0 = failure. New codes only appended. */
typedef int32_t pn_status_t;
enum {
    PN_OK = 0,
    PN_NO_DATA = 1, /* success, nothing to return (poll on an empty queue) */
    PN_E_INVALID_ARGUMENT = -1,
    PN_E_INVALID_CONFIG = -2, /* error.where names the offending config key */
    PN_E_UNSUPPORTED = -3,
    PN_E_ABI_MISMATCH = -4,
    PN_E_NOT_FOUND = -5,
    PN_E_BAD_STATE = -6,
    PN_E_OUT_OF_ORDER = -7, /* time went backwards or repeated */
    PN_E_NUMERIC = -8,      /* non-finite input or output, diverged filter */
    PN_E_OUT_OF_MEMORY = -9,
    PN_E_IO = -10,
    PN_E_INTERNAL = -11, /* a plugin threw or broke its contract */
    PN_E_BAD_INPUT = -12 /* malformed sample: wrong units, gap, truncated row */
};
#define PN_FAILED(s) ((s) < 0)

#define PN_ERROR_WHERE_SIZE 128
#define PN_ERROR_MESSAGE_SIZE 256

/* Caller-owned, fixed-size error report. Every function that takes one accepts
 * NULL. Nothing in it is heap-allocated: nothing to free, safe from any binding.
 * The callee fills it only when it returns a failure status, and writes only
 * the fields that fit in the caller's struct_size (text is truncated to fit). */
typedef struct pn_error_t {
    uint32_t struct_size; /* set by the caller: sizeof(pn_error_t) */
    pn_status_t code;
    int32_t detail; /* producer-specific: a line number, a sample index, ... */
    uint32_t reserved;
    char where[PN_ERROR_WHERE_SIZE];     /* JSON pointer to the config key, a file, or an instance name */
    char message[PN_ERROR_MESSAGE_SIZE]; /* one human-readable sentence, NUL-terminated */
} pn_error_t;

/* ------------------------------------------------------------ geodesy */

/* A point on the WGS-84 ellipsoid (1.1). The engine's geodetic origin is one:
 * the point at ENU (0, 0, 0), whose tangent plane is the ENU frame. */
typedef struct pn_geo_point_t {
    double lat_deg;  /* geodetic latitude, north positive, [-90, 90] */
    double lon_deg;  /* longitude, east positive, [-180, 180] */
    double height_m; /* height above the ellipsoid */
} pn_geo_point_t;

/* --------------------------------------------------------------- records */

/* Record type ids. Ids are bit positions in the consumes/produces masks of a
 * plugin descriptor, so they stay below 64. */
typedef uint32_t pn_record_type_t;
enum {
    PN_REC_IMU = 1,                 /* pn_imu_t: accelerometer + gyroscope, body frame */
    PN_REC_MAG = 2,                 /* pn_mag_t: magnetometer, body frame */
    PN_REC_BARO = 3,                /* pn_baro_t: static pressure */
    PN_REC_GNSS = 4,                /* pn_gnss_t: a satellite fix */
    PN_REC_GAIT_PHASE = 5,          /* pn_gait_phase_t: per-sample stance/swing decision */
    PN_REC_STEP = 6,                /* pn_step_t: a detected step (no displacement yet) */
    PN_REC_ATTITUDE = 7,            /* pn_attitude_t: body attitude in ENU */
    PN_REC_ATTITUDE_CORRECTION = 8, /* pn_attitude_correction_t: feedback to an attitude estimator */
    PN_REC_POSITION = 9,            /* pn_position_t: position with covariance and floor */
    PN_REC_STRIDE = 10              /* pn_stride_t: one step's displacement, class and covariance */
};
#define PN_REC_TYPE_COUNT 11 /* one past the highest id defined in this minor */

/* Sizes of the records as defined in 1.0. A reader accepts any record at
 * least this large (older producers never send less); later minors only
 * append, so these never change. */
#define PN_IMU_MIN_SIZE 72
#define PN_MAG_MIN_SIZE 48
#define PN_BARO_MIN_SIZE 40
#define PN_GNSS_MIN_SIZE 96
#define PN_GAIT_PHASE_MIN_SIZE 40
#define PN_STEP_MIN_SIZE 48
#define PN_ATTITUDE_MIN_SIZE 160
#define PN_ATTITUDE_CORRECTION_MIN_SIZE 72
#define PN_POSITION_MIN_SIZE 160
#define PN_STRIDE_MIN_SIZE 152
#define PN_REC_MASK(type) ((uint64_t)1 << (type))

/* Every record starts with this header. struct_size is the size of the whole
 * record as written by its producer; readers use min(struct_size, sizeof(known)).
 * Every record is at most PN_RECORD_MAX_SIZE bytes. */
#define PN_RECORD_MAX_SIZE 512
typedef struct pn_record_header_t {
    uint32_t struct_size;
    pn_record_type_t type;
    int64_t t_ns;       /* time the record describes (not when it was computed) */
    uint32_t source_id; /* 0 = app input; otherwise the engine's index of the producing stage + 1 */
    uint32_t flags;     /* per-type PN_*_FLAG_* bits */
} pn_record_header_t;

/* Accelerometer and gyroscope, same instant, body (FLU) frame, sensor biases
 * not removed. */
typedef struct pn_imu_t {
    pn_record_header_t header;
    double accel_mps2[3]; /* specific force */
    double gyro_radps[3]; /* angular rate */
} pn_imu_t;

/* Magnetic field in the body frame. */
typedef struct pn_mag_t {
    pn_record_header_t header;
    double mag_ut[3];
} pn_mag_t;

/* Static pressure. */
typedef struct pn_baro_t {
    pn_record_header_t header;
    double pressure_pa;
    double temperature_c; /* NaN when unknown */
} pn_baro_t;

/* A satellite fix, WGS-84. */
#define PN_GNSS_FLAG_HAS_VELOCITY 1u
/* pn_gnss_t.fix_type: the NMEA GGA quality codes, except 0 (GGA: no fix,
 * which is never a record) means unknown. */
#define PN_GNSS_FIX_UNKNOWN 0
#define PN_GNSS_FIX_AUTONOMOUS 1
#define PN_GNSS_FIX_DIFFERENTIAL 2
#define PN_GNSS_FIX_RTK_FIXED 4
#define PN_GNSS_FIX_RTK_FLOAT 5
#define PN_GNSS_FIX_DEAD_RECKONING 6
typedef struct pn_gnss_t {
    pn_record_header_t header;
    double lat_deg;
    double lon_deg;
    double height_m;          /* ellipsoidal height */
    double h_accuracy_m;      /* 1-sigma horizontal */
    double v_accuracy_m;      /* 1-sigma vertical */
    double vel_enu_mps[3];    /* valid when PN_GNSS_FLAG_HAS_VELOCITY */
    int64_t utc_ns;           /* UTC of the fix, 0 when unknown */
    /* 1.1 (struct_size >= 104; read a shorter record's tail as zeros) */
    int32_t satellites;       /* satellites used in the fix, 0 when unknown */
    int32_t fix_type;         /* PN_GNSS_FIX_* */
} pn_gnss_t;

/* Per-sample gait phase from a foot stance detector. t_ns is the time of the
 * IMU sample it classifies (a detector with look-ahead emits it later). */
typedef struct pn_gait_phase_t {
    pn_record_header_t header;
    int32_t stance;   /* 1 = foot still on the ground (zero velocity), 0 = moving */
    int32_t reserved;
    double statistic; /* the detector's test statistic, for plots and tuning */
} pn_gait_phase_t;

/* A step found by a step detector (chest, waist, or foot stance onset).
 * t_ns is the step's instant (peak or heel strike), the end of the interval
 * [t_start_ns, t_ns] it covers. */
#define PN_STEP_MODE_UNKNOWN 0
#define PN_STEP_MODE_STRAIGHT 1   /* level walking, heading steady */
#define PN_STEP_MODE_TURNING 2    /* level walking, heading changing */
#define PN_STEP_MODE_UPSTAIRS 3
#define PN_STEP_MODE_DOWNSTAIRS 4
#define PN_STEP_MODE_STATIC 5     /* standing still (a step record that closes a pause) */
typedef struct pn_step_t {
    pn_record_header_t header;
    int64_t t_start_ns;          /* start of the step interval */
    double accel_peak_to_peak_mps2; /* filtered acceleration range within the step (accel_max - accel_min) */
    double frequency_hz;         /* 1 / step period, 0 when unknown */
    /* 1.1 (struct_size >= 72) */
    double accel_max_mps2;       /* largest filtered acceleration within the step (the detector's signal: vertical, or the norm minus gravity) */
    double accel_min_mps2;       /* smallest filtered acceleration within the step */
    int32_t motion_mode;         /* PN_STEP_MODE_* */
    int32_t reserved;            /* 0 */
} pn_step_t;

/* Body attitude. */
#define PN_ATTITUDE_FLAG_MAG_USED 1u /* 1.1: the magnetometer corrected this attitude (its field agreed with the local one) */
typedef struct pn_attitude_t {
    pn_record_header_t header;
    double q_enu_from_body[4]; /* w, x, y, z */
    double heading_rad;        /* clockwise from north of the body x axis projected level */
    double gyro_bias_radps[3]; /* current bias estimate, body frame */
    double cov_attitude_rad2[9]; /* row-major, small-angle error in ENU; zeros when unknown */
} pn_attitude_t;

/* Feedback from a filter to the attitude estimator upstream of it: rotate the
 * estimator's attitude by the small ENU rotation and add the bias correction.
 * t_ns is the time of the sample after which it applies. */
typedef struct pn_attitude_correction_t {
    pn_record_header_t header;
    double rotation_enu_rad[3];    /* q_new = exp(rotation) * q_old */
    double gyro_bias_delta_radps[3];
} pn_attitude_correction_t;

/* Position estimate. */
#define PN_POSITION_FLAG_HAS_VELOCITY 1u
#define PN_POSITION_FLAG_HAS_FLOOR 2u
#define PN_POSITION_FLAG_HAS_PARTICLES 4u /* 1.1: live_particles is set (a particle filter's estimate) */
#define PN_POSITION_FLAG_RECOVERED 8u     /* 1.1: the estimator lost track and restarted since its previous output */
#define PN_POSITION_SOURCE_INERTIAL 0
#define PN_POSITION_SOURCE_FUSED 1
#define PN_POSITION_SOURCE_GNSS 2
#define PN_POSITION_SOURCE_MAP 3
typedef struct pn_position_t {
    pn_record_header_t header;
    double pos_enu_m[3];    /* from the start point */
    double vel_enu_mps[3];  /* valid when PN_POSITION_FLAG_HAS_VELOCITY */
    double cov_enu_m2[9];   /* row-major, position covariance */
    double heading_rad;     /* clockwise from north */
    int32_t floor;          /* valid when PN_POSITION_FLAG_HAS_FLOOR; 0 = start floor */
    int32_t source;         /* PN_POSITION_SOURCE_* */
    /* 1.1 (struct_size >= 168) */
    uint32_t live_particles; /* valid when PN_POSITION_FLAG_HAS_PARTICLES */
    uint32_t recoveries;     /* times the estimator restarted since the last reset */
} pn_position_t;

/* One step's displacement. Emitted once per step by a position filter. */
#define PN_STRIDE_CLASS_UNKNOWN 0
#define PN_STRIDE_CLASS_LEVEL 1
#define PN_STRIDE_CLASS_STAIRS_UP 2
#define PN_STRIDE_CLASS_STAIRS_DOWN 3
typedef struct pn_stride_t {
    pn_record_header_t header;       /* t_ns: end of the step (for a foot: mid-stance after it) */
    int64_t t_start_ns;
    double displacement_enu_m[3];
    double length_m;                 /* horizontal length */
    double heading_change_rad;       /* clockwise positive, over the step */
    double cov_displacement_m2[9];   /* row-major */
    int32_t stride_class;            /* PN_STRIDE_CLASS_* */
    int32_t index;                   /* 0, 1, 2, ... since the last reset */
} pn_stride_t;

#ifdef __cplusplus
}
#endif

#endif /* PEDNAV_PN_TYPES_H */
