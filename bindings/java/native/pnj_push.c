/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Pushing samples: one at a time, many from Java arrays in one call (copied
 * chunk by chunk into pn_imu_t), and a RecordBuffer's direct ByteBuffer of
 * ready-made records handed to the engine in place.
 */
#include <string.h>

#include "pnj_common.h"

/* Samples converted per pn_engine_push_imu call in the array path. */
#define PNJ_IMU_CHUNK 64
/* Record pointers handed to pn_engine_push_records per call. */
#define PNJ_RECORD_CHUNK 256

static void set_header(pn_record_header_t *h, uint32_t size, pn_record_type_t type, jlong t_ns) {
    h->struct_size = size;
    h->type = type;
    h->t_ns = (int64_t)t_ns;
    h->source_id = 0;
    h->flags = 0;
}

static void push_record(JNIEnv *env, jlong handle, const pn_record_header_t *record) {
    pn_engine_t *engine = pnj_engine_of(env, handle);
    pn_error_t err;
    if (!engine) return;
    pnj_init_error(&err);
    pnj_check(env, pn_engine_push(engine, record, &err), &err);
}

JNIEXPORT void JNICALL Java_org_pednav_Engine_nativePushImu(JNIEnv *env, jclass cls, jlong handle, jlong t_ns,
                                                            jdouble ax, jdouble ay, jdouble az, jdouble gx,
                                                            jdouble gy, jdouble gz) {
    pn_imu_t imu;
    pn_engine_t *engine = pnj_engine_of(env, handle);
    pn_error_t err;
    (void)cls;
    if (!engine) return;
    memset(&imu, 0, sizeof imu);
    set_header(&imu.header, sizeof imu, PN_REC_IMU, t_ns);
    imu.accel_mps2[0] = ax;
    imu.accel_mps2[1] = ay;
    imu.accel_mps2[2] = az;
    imu.gyro_radps[0] = gx;
    imu.gyro_radps[1] = gy;
    imu.gyro_radps[2] = gz;
    pnj_init_error(&err);
    pnj_check(env, pn_engine_push_imu(engine, &imu, 1, sizeof imu, &err), &err);
}

/* All samples in one JNI call: copied chunk by chunk into an array of
 * pn_imu_t and handed over with an explicit stride. On a rejected sample
 * the exception's detail is its index in the whole Java array. */
JNIEXPORT void JNICALL Java_org_pednav_Engine_nativePushImuBulk(JNIEnv *env, jclass cls, jlong handle,
                                                                jlongArray t_ns, jdoubleArray accel,
                                                                jdoubleArray gyro) {
    pn_imu_t samples[PNJ_IMU_CHUNK];
    jlong t_buf[PNJ_IMU_CHUNK];
    jdouble accel_buf[3 * PNJ_IMU_CHUNK];
    jdouble gyro_buf[3 * PNJ_IMU_CHUNK];
    pn_engine_t *engine;
    pn_error_t err;
    jsize n, start;
    (void)cls;

    if (!t_ns || !accel || !gyro) {
        pnj_throw_java(env, "java/lang/NullPointerException", "tNs, accel and gyro must not be null");
        return;
    }
    n = (*env)->GetArrayLength(env, t_ns);
    if ((*env)->GetArrayLength(env, accel) / 3 != n || (*env)->GetArrayLength(env, accel) % 3 != 0 ||
        (*env)->GetArrayLength(env, gyro) / 3 != n || (*env)->GetArrayLength(env, gyro) % 3 != 0) {
        pnj_throw_java(env, "java/lang/IllegalArgumentException",
                       "accel and gyro must hold 3 values per time stamp");
        return;
    }
    engine = pnj_engine_of(env, handle);
    if (!engine) return;
    memset(samples, 0, sizeof samples);

    for (start = 0; start < n; start += PNJ_IMU_CHUNK) {
        const jsize m = n - start < PNJ_IMU_CHUNK ? n - start : PNJ_IMU_CHUNK;
        pn_status_t status;
        jsize i;
        (*env)->GetLongArrayRegion(env, t_ns, start, m, t_buf);
        (*env)->GetDoubleArrayRegion(env, accel, 3 * start, 3 * m, accel_buf);
        (*env)->GetDoubleArrayRegion(env, gyro, 3 * start, 3 * m, gyro_buf);
        if ((*env)->ExceptionCheck(env)) return;
        for (i = 0; i < m; ++i) {
            pn_imu_t *s = &samples[i];
            set_header(&s->header, sizeof *s, PN_REC_IMU, t_buf[i]);
            s->accel_mps2[0] = accel_buf[3 * i];
            s->accel_mps2[1] = accel_buf[3 * i + 1];
            s->accel_mps2[2] = accel_buf[3 * i + 2];
            s->gyro_radps[0] = gyro_buf[3 * i];
            s->gyro_radps[1] = gyro_buf[3 * i + 1];
            s->gyro_radps[2] = gyro_buf[3 * i + 2];
        }
        pnj_init_error(&err);
        status = pn_engine_push_imu(engine, samples, (size_t)m, sizeof(pn_imu_t), &err);
        if (PN_FAILED(status)) {
            err.detail += (int32_t)start;
            pnj_throw_pednav(env, status, &err);
            return;
        }
    }
}

JNIEXPORT void JNICALL Java_org_pednav_Engine_nativePushMag(JNIEnv *env, jclass cls, jlong handle, jlong t_ns,
                                                            jdouble mx, jdouble my, jdouble mz) {
    pn_mag_t mag;
    (void)cls;
    memset(&mag, 0, sizeof mag);
    set_header(&mag.header, sizeof mag, PN_REC_MAG, t_ns);
    mag.mag_ut[0] = mx;
    mag.mag_ut[1] = my;
    mag.mag_ut[2] = mz;
    push_record(env, handle, &mag.header);
}

JNIEXPORT void JNICALL Java_org_pednav_Engine_nativePushBaro(JNIEnv *env, jclass cls, jlong handle,
                                                             jlong t_ns, jdouble pressure_pa,
                                                             jdouble temperature_c) {
    pn_baro_t baro;
    (void)cls;
    memset(&baro, 0, sizeof baro);
    set_header(&baro.header, sizeof baro, PN_REC_BARO, t_ns);
    baro.pressure_pa = pressure_pa;
    baro.temperature_c = temperature_c;
    push_record(env, handle, &baro.header);
}

JNIEXPORT void JNICALL Java_org_pednav_Engine_nativePushGnss(JNIEnv *env, jclass cls, jlong handle,
                                                             jlong t_ns, jdouble lat_deg, jdouble lon_deg,
                                                             jdouble height_m, jdouble h_accuracy_m,
                                                             jdouble v_accuracy_m, jboolean has_velocity,
                                                             jdouble ve, jdouble vn, jdouble vu,
                                                             jlong utc_ns) {
    pn_gnss_t gnss;
    (void)cls;
    memset(&gnss, 0, sizeof gnss);
    set_header(&gnss.header, sizeof gnss, PN_REC_GNSS, t_ns);
    gnss.lat_deg = lat_deg;
    gnss.lon_deg = lon_deg;
    gnss.height_m = height_m;
    gnss.h_accuracy_m = h_accuracy_m;
    gnss.v_accuracy_m = v_accuracy_m;
    if (has_velocity) {
        gnss.header.flags = PN_GNSS_FLAG_HAS_VELOCITY;
        gnss.vel_enu_mps[0] = ve;
        gnss.vel_enu_mps[1] = vn;
        gnss.vel_enu_mps[2] = vu;
    }
    gnss.utc_ns = (int64_t)utc_ns;
    push_record(env, handle, &gnss.header);
}

/* Size a record of an input type must have in a RecordBuffer, 0 for other types. */
static uint32_t input_record_size(pn_record_type_t type) {
    switch (type) {
        case PN_REC_IMU: return (uint32_t)sizeof(pn_imu_t);
        case PN_REC_MAG: return (uint32_t)sizeof(pn_mag_t);
        case PN_REC_BARO: return (uint32_t)sizeof(pn_baro_t);
        case PN_REC_GNSS: return (uint32_t)sizeof(pn_gnss_t);
        default: return 0;
    }
}

/* The `count` records in the first `bytes` bytes of a direct ByteBuffer
 * (org.pednav.RecordBuffer: engine records back to back, native byte order,
 * 8-byte aligned) in one JNI call. IMU-only buffers go to pn_engine_push_imu
 * as one array; mixed ones to pn_engine_push_records, PNJ_RECORD_CHUNK
 * pointers at a time. Each header is checked first, so a buffer that does not
 * hold what it claims is an IllegalArgumentException, never a bad read. On a
 * rejected record the exception's detail is its index in the buffer. */
JNIEXPORT void JNICALL Java_org_pednav_Engine_nativePushBuffer(JNIEnv *env, jclass cls, jlong handle,
                                                               jobject buffer, jint bytes, jint count,
                                                               jboolean imu_only) {
    const pn_record_header_t *records[PNJ_RECORD_CHUNK];
    unsigned char *base;
    pn_engine_t *engine;
    pn_error_t err;
    size_t offset = 0;
    jint start = 0, i;
    (void)cls;
    if (bytes < 0 || count < 0) {
        pnj_throw_java(env, "java/lang/IllegalArgumentException", "negative record buffer size");
        return;
    }
    base = pnj_direct_buffer(env, buffer, bytes,
                             "the record buffer must be a direct, 8-byte aligned ByteBuffer");
    if (!base) return;
    engine = pnj_engine_of(env, handle);
    if (!engine) return;
    for (i = 0; i < count; ++i) {
        pn_record_header_t h;
        uint32_t want;
        if (offset + sizeof h > (size_t)bytes) break;
        memcpy(&h, base + offset, sizeof h);
        want = input_record_size(h.type);
        if (!want || h.struct_size != want || (imu_only && h.type != PN_REC_IMU)) break;
        offset += want;
    }
    if (i != count || offset != (size_t)bytes) {
        pnj_throw_java(env, "java/lang/IllegalArgumentException",
                       "the record buffer does not hold the records it counts");
        return;
    }
    pnj_init_error(&err);
    if (imu_only) {
        pnj_check(env,
                  pn_engine_push_imu(engine, (const pn_imu_t *)base, (size_t)count, sizeof(pn_imu_t), &err),
                  &err);
        return;
    }
    offset = 0;
    while (start < count) {
        const jint m = count - start < PNJ_RECORD_CHUNK ? count - start : PNJ_RECORD_CHUNK;
        pn_status_t status;
        for (i = 0; i < m; ++i) {
            records[i] = (const pn_record_header_t *)(base + offset);
            offset += records[i]->struct_size;
        }
        status = pn_engine_push_records(engine, records, (size_t)m, &err);
        if (PN_FAILED(status)) {
            err.detail += (int32_t)start;
            pnj_throw_pednav(env, status, &err);
            return;
        }
        start += m;
    }
}
