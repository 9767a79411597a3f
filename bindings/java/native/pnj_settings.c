/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Stream control and settings: flush, reset, start point, initial attitude,
 * geodetic origin and the ENU <-> WGS-84 conversions, maps, live
 * reconfiguration, the output mask.
 */
#include <stdlib.h>

#include "pnj_common.h"

JNIEXPORT void JNICALL Java_org_pednav_Engine_nativeFlush(JNIEnv *env, jclass cls, jlong handle) {
    pn_engine_t *engine = pnj_engine_of(env, handle);
    pn_error_t err;
    (void)cls;
    if (!engine) return;
    pnj_init_error(&err);
    pnj_check(env, pn_engine_flush(engine, &err), &err);
}

JNIEXPORT void JNICALL Java_org_pednav_Engine_nativeReset(JNIEnv *env, jclass cls, jlong handle) {
    pn_engine_t *engine = pnj_engine_of(env, handle);
    pn_error_t err;
    (void)cls;
    if (!engine) return;
    pnj_init_error(&err);
    pnj_check(env, pn_engine_reset(engine, &err), &err);
}

JNIEXPORT void JNICALL Java_org_pednav_Engine_nativeSetStart(JNIEnv *env, jclass cls, jlong handle, jdouble x,
                                                             jdouble y, jdouble z, jdouble heading_deg) {
    pn_engine_t *engine = pnj_engine_of(env, handle);
    const double pos_enu_m[3] = {x, y, z};
    pn_error_t err;
    (void)cls;
    if (!engine) return;
    pnj_init_error(&err);
    pnj_check(env, pn_engine_set_start(engine, pos_enu_m, heading_deg, &err), &err);
}

JNIEXPORT void JNICALL Java_org_pednav_Engine_nativeSetAttitude(JNIEnv *env, jclass cls, jlong handle,
                                                                jdouble qw, jdouble qx, jdouble qy,
                                                                jdouble qz) {
    pn_engine_t *engine = pnj_engine_of(env, handle);
    const double q_enu_from_body[4] = {qw, qx, qy, qz};
    pn_error_t err;
    (void)cls;
    if (!engine) return;
    pnj_init_error(&err);
    pnj_check(env, pn_engine_set_attitude(engine, q_enu_from_body, &err), &err);
}

/* --------------------------------------------------------------- origin */

JNIEXPORT void JNICALL Java_org_pednav_Engine_nativeSetOrigin(JNIEnv *env, jclass cls, jlong handle,
                                                              jdouble lat_deg, jdouble lon_deg,
                                                              jdouble height_m) {
    pn_engine_t *engine = pnj_engine_of(env, handle);
    pn_geo_point_t origin;
    pn_error_t err;
    (void)cls;
    if (!engine) return;
    origin.lat_deg = lat_deg;
    origin.lon_deg = lon_deg;
    origin.height_m = height_m;
    pnj_init_error(&err);
    pnj_check(env, pn_engine_set_origin(engine, &origin, &err), &err);
}

/* Writes {lat_deg, lon_deg, height_m} or {east, north, up} into out[3]:
 * true, or false when the status is PN_NO_DATA (no origin yet). */
static jboolean put3(JNIEnv *env, pn_status_t status, const char *where, jdoubleArray out,
                     const double v[3]) {
    if (status == PN_NO_DATA) return JNI_FALSE;
    if (status != PN_OK) {
        pnj_throw_status(env, PN_FAILED(status) ? status : PN_E_INTERNAL, where, "the conversion failed");
        return JNI_FALSE;
    }
    (*env)->SetDoubleArrayRegion(env, out, 0, 3, v);
    return JNI_TRUE;
}

static jboolean check_out3(JNIEnv *env, jdoubleArray out) {
    if (!out || (*env)->GetArrayLength(env, out) < 3) {
        pnj_throw_java(env, "java/lang/IllegalArgumentException", "the result array must hold 3 values");
        return JNI_FALSE;
    }
    return JNI_TRUE;
}

JNIEXPORT jboolean JNICALL Java_org_pednav_Engine_nativeGetOrigin(JNIEnv *env, jclass cls, jlong handle,
                                                                  jdoubleArray out) {
    pn_engine_t *engine = pnj_engine_of(env, handle);
    pn_geo_point_t o;
    double v[3];
    (void)cls;
    if (!engine || !check_out3(env, out)) return JNI_FALSE;
    const pn_status_t status = pn_engine_get_origin(engine, &o);
    v[0] = o.lat_deg;
    v[1] = o.lon_deg;
    v[2] = o.height_m;
    return put3(env, status, "origin", out, v);
}

JNIEXPORT jboolean JNICALL Java_org_pednav_Engine_nativeGeoFromEnu(JNIEnv *env, jclass cls, jlong handle,
                                                                   jdouble east_m, jdouble north_m,
                                                                   jdouble up_m, jdoubleArray out) {
    pn_engine_t *engine = pnj_engine_of(env, handle);
    const double pos_enu_m[3] = {east_m, north_m, up_m};
    pn_geo_point_t g;
    double v[3];
    (void)cls;
    if (!engine || !check_out3(env, out)) return JNI_FALSE;
    const pn_status_t status = pn_engine_geo_from_enu(engine, pos_enu_m, &g);
    v[0] = g.lat_deg;
    v[1] = g.lon_deg;
    v[2] = g.height_m;
    return put3(env, status, "geo_from_enu", out, v);
}

JNIEXPORT jboolean JNICALL Java_org_pednav_Engine_nativeEnuFromGeo(JNIEnv *env, jclass cls, jlong handle,
                                                                   jdouble lat_deg, jdouble lon_deg,
                                                                   jdouble height_m, jdoubleArray out) {
    pn_engine_t *engine = pnj_engine_of(env, handle);
    pn_geo_point_t point;
    double pos_enu_m[3] = {0.0, 0.0, 0.0};
    (void)cls;
    if (!engine || !check_out3(env, out)) return JNI_FALSE;
    point.lat_deg = lat_deg;
    point.lon_deg = lon_deg;
    point.height_m = height_m;
    return put3(env, pn_engine_enu_from_geo(engine, &point, pos_enu_m), "enu_from_geo", out, pos_enu_m);
}

/* ------------------------------------------------------ maps and params */

typedef pn_status_t (*text_call_fn)(pn_engine_t *engine, const char *name, const char *bytes, size_t size,
                                    pn_error_t *err);

/* Calls fn with NUL-terminated copies of `name_utf8` and `bytes` (and the
 * length of the latter), throwing what it reports. */
static void call_with_texts(JNIEnv *env, jlong handle, jbyteArray name_utf8, jbyteArray bytes_array,
                            text_call_fn fn) {
    pn_engine_t *engine = pnj_engine_of(env, handle);
    char *name, *bytes;
    size_t size = 0;
    pn_error_t err;
    if (!engine) return;
    name = pnj_copy_bytes(env, name_utf8, NULL);
    if (!name) return;
    bytes = pnj_copy_bytes(env, bytes_array, &size);
    if (bytes) {
        pnj_init_error(&err);
        pnj_check(env, fn(engine, name, bytes, size, &err), &err);
    }
    free(bytes);
    free(name);
}

static pn_status_t load_map(pn_engine_t *engine, const char *format, const char *bytes, size_t size,
                            pn_error_t *err) {
    return pn_engine_load_map(engine, format, bytes, size, err);
}

JNIEXPORT void JNICALL Java_org_pednav_Engine_nativeLoadMap(JNIEnv *env, jclass cls, jlong handle,
                                                            jbyteArray format_utf8, jbyteArray map_bytes) {
    (void)cls;
    call_with_texts(env, handle, format_utf8, map_bytes, load_map);
}

JNIEXPORT void JNICALL Java_org_pednav_Engine_nativeReconfigure(JNIEnv *env, jclass cls, jlong handle,
                                                                jbyteArray stage_utf8,
                                                                jbyteArray params_utf8) {
    (void)cls;
    call_with_texts(env, handle, stage_utf8, params_utf8, pn_engine_reconfigure);
}

JNIEXPORT void JNICALL Java_org_pednav_Engine_nativeSetOutputMask(JNIEnv *env, jclass cls, jlong handle,
                                                                  jlong mask) {
    pn_engine_t *engine = pnj_engine_of(env, handle);
    pn_status_t status;
    (void)cls;
    if (!engine) return;
    status = pn_engine_set_output_mask(engine, (uint64_t)mask);
    if (PN_FAILED(status))
        pnj_throw_status(
            env, status, "output_mask",
            "only POSITION, STRIDE, STEP, ATTITUDE, GAIT_PHASE and ATTITUDE_CORRECTION can be polled; "
            "the mask stays as it was");
}
