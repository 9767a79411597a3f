/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Polling: pn_engine_poll_many straight into a direct ByteBuffer of
 * pn_output_t slots, decoded on the Java side (org.pednav.RecordLayout), and
 * the layout that decoder relies on, checked once when the class loads.
 */
#include <stddef.h>

#include "pnj_common.h"

/* Pops up to `capacity` records into the slots of `buffer`; returns how many. */
JNIEXPORT jint JNICALL Java_org_pednav_Engine_nativePollMany(JNIEnv *env, jclass cls, jlong handle,
                                                             jobject buffer, jint capacity) {
    pn_engine_t *engine = pnj_engine_of(env, handle);
    unsigned char *base;
    size_t count = 0;
    pn_status_t status;
    (void)cls;
    if (!engine) return 0;
    if (capacity <= 0) {
        pnj_throw_java(env, "java/lang/IllegalArgumentException", "poll capacity must be positive");
        return 0;
    }
    base =
        pnj_direct_buffer(env, buffer, (jlong)capacity * (jlong)sizeof(pn_output_t),
                          "the poll buffer must be a direct, 8-byte aligned ByteBuffer of pn_output_t slots");
    if (!base) return 0;
    status = pn_engine_poll_many(engine, (pn_output_t *)base, (size_t)capacity, &count);
    if (PN_FAILED(status)) {
        pnj_throw_status(env, status, "poll", "pn_engine_poll_many failed");
        return 0;
    }
    return (jint)count;
}

/* sizeof and offsetof values the Java decoder hard-codes, in the order of
 * RecordLayout.EXPECTED. */
JNIEXPORT jintArray JNICALL Java_org_pednav_Engine_nativeLayout(JNIEnv *env, jclass cls) {
    const jint layout[] = {
        (jint)sizeof(pn_output_t),
        (jint)offsetof(pn_record_header_t, struct_size),
        (jint)offsetof(pn_record_header_t, type),
        (jint)offsetof(pn_record_header_t, t_ns),
        (jint)offsetof(pn_record_header_t, source_id),
        (jint)offsetof(pn_record_header_t, flags),
        (jint)sizeof(pn_imu_t),
        (jint)offsetof(pn_imu_t, accel_mps2),
        (jint)offsetof(pn_imu_t, gyro_radps),
        (jint)sizeof(pn_mag_t),
        (jint)offsetof(pn_mag_t, mag_ut),
        (jint)sizeof(pn_baro_t),
        (jint)offsetof(pn_baro_t, pressure_pa),
        (jint)offsetof(pn_baro_t, temperature_c),
        (jint)sizeof(pn_gnss_t),
        (jint)offsetof(pn_gnss_t, lat_deg),
        (jint)offsetof(pn_gnss_t, lon_deg),
        (jint)offsetof(pn_gnss_t, height_m),
        (jint)offsetof(pn_gnss_t, h_accuracy_m),
        (jint)offsetof(pn_gnss_t, v_accuracy_m),
        (jint)offsetof(pn_gnss_t, vel_enu_mps),
        (jint)offsetof(pn_gnss_t, utc_ns),
        (jint)offsetof(pn_position_t, pos_enu_m),
        (jint)offsetof(pn_position_t, vel_enu_mps),
        (jint)offsetof(pn_position_t, cov_enu_m2),
        (jint)offsetof(pn_position_t, heading_rad),
        (jint)offsetof(pn_position_t, floor),
        (jint)offsetof(pn_position_t, source),
        (jint)offsetof(pn_position_t, live_particles),
        (jint)offsetof(pn_position_t, recoveries),
        (jint)offsetof(pn_stride_t, t_start_ns),
        (jint)offsetof(pn_stride_t, displacement_enu_m),
        (jint)offsetof(pn_stride_t, length_m),
        (jint)offsetof(pn_stride_t, heading_change_rad),
        (jint)offsetof(pn_stride_t, cov_displacement_m2),
        (jint)offsetof(pn_stride_t, stride_class),
        (jint)offsetof(pn_stride_t, index),
        (jint)offsetof(pn_step_t, t_start_ns),
        (jint)offsetof(pn_step_t, accel_peak_to_peak_mps2),
        (jint)offsetof(pn_step_t, frequency_hz),
        (jint)offsetof(pn_step_t, accel_max_mps2),
        (jint)offsetof(pn_step_t, accel_min_mps2),
        (jint)offsetof(pn_step_t, motion_mode),
        (jint)offsetof(pn_attitude_t, q_enu_from_body),
        (jint)offsetof(pn_attitude_t, heading_rad),
        (jint)offsetof(pn_attitude_t, gyro_bias_radps),
        (jint)offsetof(pn_attitude_t, cov_attitude_rad2),
        (jint)offsetof(pn_gait_phase_t, stance),
        (jint)offsetof(pn_gait_phase_t, statistic),
        (jint)offsetof(pn_attitude_correction_t, rotation_enu_rad),
        (jint)offsetof(pn_attitude_correction_t, gyro_bias_delta_radps),
    };
    const jsize n = (jsize)(sizeof layout / sizeof layout[0]);
    jintArray out = (*env)->NewIntArray(env, n);
    (void)cls;
    if (out) (*env)->SetIntArrayRegion(env, out, 0, n, layout);
    return out;
}
