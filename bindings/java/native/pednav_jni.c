/* SPDX-License-Identifier: Apache-2.0 */
/*
 * JNI glue between org.pednav.Engine and the app-facing C API (pn_engine.h).
 *
 * Only the C header is used, so the same file builds for desktop JVMs and
 * with the Android NDK. Rules kept throughout:
 *   - no Java exception is left pending across a call into the engine;
 *   - text from the engine (error fields, describe) crosses as UTF-8 bytes and
 *     is decoded on the Java side (NewStringUTF expects modified UTF-8);
 *   - the engine never sees a Java array: samples are copied into native
 *     buffers first, so no critical section is held while the engine runs;
 *   - every failure becomes a Java exception, never an abort.
 */
#include <stdlib.h>
#include <string.h>

#include <jni.h>
#include <pednav/pn_engine.h>

/* Samples converted per pn_engine_push_imu call in the bulk path. */
#define PNJ_IMU_CHUNK 64

/* Layout of the scratch arrays nativePoll fills; mirrored in Engine.java. */
#define PNJ_POLL_LONGS 8
#define PNJ_POLL_DOUBLES 24

static jclass g_pednav_exception;   /* org.pednav.PednavException (global ref) */
static jmethodID g_from_native;     /* PednavException.fromNative(int, byte[], byte[], byte[], int) */

JNIEXPORT jint JNICALL JNI_OnLoad(JavaVM *vm, void *reserved) {
    JNIEnv *env = NULL;
    jclass local;
    (void)reserved;
    if ((*vm)->GetEnv(vm, (void **)&env, JNI_VERSION_1_6) != JNI_OK) return JNI_ERR;
    /* Looked up here: on Android only JNI_OnLoad runs with the app's class loader. */
    local = (*env)->FindClass(env, "org/pednav/PednavException");
    if (!local) return JNI_ERR;
    g_pednav_exception = (jclass)(*env)->NewGlobalRef(env, local);
    (*env)->DeleteLocalRef(env, local);
    if (!g_pednav_exception) return JNI_ERR;
    g_from_native = (*env)->GetStaticMethodID(env, g_pednav_exception, "fromNative",
                                              "(I[B[B[BI)Lorg/pednav/PednavException;");
    if (!g_from_native) return JNI_ERR;
    return JNI_VERSION_1_6;
}

JNIEXPORT void JNICALL JNI_OnUnload(JavaVM *vm, void *reserved) {
    JNIEnv *env = NULL;
    (void)reserved;
    if ((*vm)->GetEnv(vm, (void **)&env, JNI_VERSION_1_6) != JNI_OK) return;
    if (g_pednav_exception) (*env)->DeleteGlobalRef(env, g_pednav_exception);
    g_pednav_exception = NULL;
}

/* ---------------------------------------------------------------- errors */

static void throw_java(JNIEnv *env, const char *class_name, const char *message) {
    jclass cls;
    if ((*env)->ExceptionCheck(env)) return;
    cls = (*env)->FindClass(env, class_name);
    if (cls) {
        (*env)->ThrowNew(env, cls, message);
        (*env)->DeleteLocalRef(env, cls);
    }
}

/* A byte[] holding at most `max` bytes of `text`, up to its first NUL. */
static jbyteArray utf8_bytes(JNIEnv *env, const char *text, size_t max) {
    size_t n = 0;
    jbyteArray out;
    if (!text) text = "";
    while (n < max && text[n] != '\0') ++n;
    out = (*env)->NewByteArray(env, (jsize)n);
    if (out && n) (*env)->SetByteArrayRegion(env, out, 0, (jsize)n, (const jbyte *)text);
    return out;
}

/* Throws org.pednav.PednavException built from a failed status and its error. */
static void throw_pednav(JNIEnv *env, pn_status_t status, const pn_error_t *err) {
    const char *name = pn_status_name(status);
    jbyteArray jname, jwhere, jmessage;
    jthrowable exc;
    if ((*env)->ExceptionCheck(env)) return;
    jname = utf8_bytes(env, name, strlen(name));
    jwhere = utf8_bytes(env, err->where, sizeof err->where);
    jmessage = utf8_bytes(env, err->message, sizeof err->message);
    if (!jname || !jwhere || !jmessage) return; /* OutOfMemoryError pending */
    exc = (jthrowable)(*env)->CallStaticObjectMethod(env, g_pednav_exception, g_from_native, (jint)status, jname,
                                                      jwhere, jmessage, (jint)err->detail);
    if (exc && !(*env)->ExceptionCheck(env)) (*env)->Throw(env, exc);
}

static void init_error(pn_error_t *err) {
    memset(err, 0, sizeof *err);
    err->struct_size = sizeof *err;
}

/* The engine behind a handle, or NULL with IllegalStateException thrown. */
static pn_engine_t *engine_of(JNIEnv *env, jlong handle) {
    pn_engine_t *engine = (pn_engine_t *)(intptr_t)handle;
    if (!engine) throw_java(env, "java/lang/IllegalStateException", "the engine is closed");
    return engine;
}

static void check_status(JNIEnv *env, pn_status_t status, const pn_error_t *err) {
    if (PN_FAILED(status)) throw_pednav(env, status, err);
}

/* --------------------------------------------------------------- create */

/* NUL-terminated native copy of a byte[]; NULL with an exception pending. */
static char *copy_bytes(JNIEnv *env, jbyteArray bytes, size_t *len) {
    jsize n;
    char *out;
    if (!bytes) {
        throw_java(env, "java/lang/NullPointerException", "null byte array");
        return NULL;
    }
    n = (*env)->GetArrayLength(env, bytes);
    out = (char *)malloc((size_t)n + 1);
    if (!out) {
        throw_java(env, "java/lang/OutOfMemoryError", "pednav: no memory for a string copy");
        return NULL;
    }
    (*env)->GetByteArrayRegion(env, bytes, 0, n, (jbyte *)out);
    out[n] = '\0';
    if (len) *len = (size_t)n;
    return out;
}

JNIEXPORT jlong JNICALL Java_org_pednav_Engine_nativeCreate(JNIEnv *env, jclass cls, jbyteArray config_utf8,
                                                            jobjectArray plugin_dirs_utf8) {
    pn_engine_create_info_t info;
    pn_error_t err;
    pn_engine_t *engine = NULL;
    pn_status_t status;
    char *config;
    char **dirs = NULL;
    size_t config_len = 0;
    jsize dir_count = 0, i;
    (void)cls;

    config = copy_bytes(env, config_utf8, &config_len);
    if (!config) return 0;
    if (plugin_dirs_utf8) dir_count = (*env)->GetArrayLength(env, plugin_dirs_utf8);
    if (dir_count > 0) {
        dirs = (char **)calloc((size_t)dir_count, sizeof *dirs);
        if (!dirs) throw_java(env, "java/lang/OutOfMemoryError", "pednav: no memory for plugin directories");
    }
    for (i = 0; dirs && i < dir_count; ++i) {
        jbyteArray dir = (jbyteArray)(*env)->GetObjectArrayElement(env, plugin_dirs_utf8, i);
        dirs[i] = copy_bytes(env, dir, NULL);
        if (dir) (*env)->DeleteLocalRef(env, dir);
        if (!dirs[i]) break;
    }

    if (!(*env)->ExceptionCheck(env)) {
        memset(&info, 0, sizeof info);
        info.abi_version = PN_ABI_VERSION;
        info.struct_size = sizeof info;
        info.config_json = config;
        info.config_len = config_len;
        info.plugin_dirs = (const char *const *)dirs;
        info.plugin_dir_count = (uint32_t)dir_count;
        init_error(&err);
        status = pn_engine_create(&info, &engine, &err);
        if (PN_FAILED(status) || !engine) {
            if (!PN_FAILED(status)) status = PN_E_INTERNAL;
            throw_pednav(env, status, &err);
            engine = NULL;
        }
    }

    for (i = 0; dirs && i < dir_count; ++i) free(dirs[i]);
    free(dirs);
    free(config);
    return (jlong)(intptr_t)engine;
}

JNIEXPORT void JNICALL Java_org_pednav_Engine_nativeDestroy(JNIEnv *env, jclass cls, jlong handle) {
    (void)env;
    (void)cls;
    pn_engine_destroy((pn_engine_t *)(intptr_t)handle);
}

/* ----------------------------------------------------------------- push */

static void set_header(pn_record_header_t *h, uint32_t size, pn_record_type_t type, jlong t_ns) {
    h->struct_size = size;
    h->type = type;
    h->t_ns = (int64_t)t_ns;
    h->source_id = 0;
    h->flags = 0;
}

static void push_record(JNIEnv *env, jlong handle, const pn_record_header_t *record) {
    pn_engine_t *engine = engine_of(env, handle);
    pn_error_t err;
    if (!engine) return;
    init_error(&err);
    check_status(env, pn_engine_push(engine, record, &err), &err);
}

JNIEXPORT void JNICALL Java_org_pednav_Engine_nativePushImu(JNIEnv *env, jclass cls, jlong handle, jlong t_ns,
                                                            jdouble ax, jdouble ay, jdouble az, jdouble gx,
                                                            jdouble gy, jdouble gz) {
    pn_imu_t imu;
    pn_engine_t *engine = engine_of(env, handle);
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
    init_error(&err);
    check_status(env, pn_engine_push_imu(engine, &imu, 1, sizeof imu, &err), &err);
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
        throw_java(env, "java/lang/NullPointerException", "tNs, accel and gyro must not be null");
        return;
    }
    n = (*env)->GetArrayLength(env, t_ns);
    if ((*env)->GetArrayLength(env, accel) / 3 != n || (*env)->GetArrayLength(env, accel) % 3 != 0 ||
        (*env)->GetArrayLength(env, gyro) / 3 != n || (*env)->GetArrayLength(env, gyro) % 3 != 0) {
        throw_java(env, "java/lang/IllegalArgumentException", "accel and gyro must hold 3 values per time stamp");
        return;
    }
    engine = engine_of(env, handle);
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
        init_error(&err);
        status = pn_engine_push_imu(engine, samples, (size_t)m, sizeof(pn_imu_t), &err);
        if (PN_FAILED(status)) {
            err.detail += (int32_t)start;
            throw_pednav(env, status, &err);
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

JNIEXPORT void JNICALL Java_org_pednav_Engine_nativePushBaro(JNIEnv *env, jclass cls, jlong handle, jlong t_ns,
                                                             jdouble pressure_pa, jdouble temperature_c) {
    pn_baro_t baro;
    (void)cls;
    memset(&baro, 0, sizeof baro);
    set_header(&baro.header, sizeof baro, PN_REC_BARO, t_ns);
    baro.pressure_pa = pressure_pa;
    baro.temperature_c = temperature_c;
    push_record(env, handle, &baro.header);
}

JNIEXPORT void JNICALL Java_org_pednav_Engine_nativePushGnss(JNIEnv *env, jclass cls, jlong handle, jlong t_ns,
                                                             jdouble lat_deg, jdouble lon_deg, jdouble height_m,
                                                             jdouble h_accuracy_m, jdouble v_accuracy_m,
                                                             jboolean has_velocity, jdouble ve, jdouble vn,
                                                             jdouble vu, jlong utc_ns) {
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

/* -------------------------------------------------------------- control */

JNIEXPORT void JNICALL Java_org_pednav_Engine_nativeFlush(JNIEnv *env, jclass cls, jlong handle) {
    pn_engine_t *engine = engine_of(env, handle);
    pn_error_t err;
    (void)cls;
    if (!engine) return;
    init_error(&err);
    check_status(env, pn_engine_flush(engine, &err), &err);
}

JNIEXPORT void JNICALL Java_org_pednav_Engine_nativeReset(JNIEnv *env, jclass cls, jlong handle) {
    pn_engine_t *engine = engine_of(env, handle);
    pn_error_t err;
    (void)cls;
    if (!engine) return;
    init_error(&err);
    check_status(env, pn_engine_reset(engine, &err), &err);
}

JNIEXPORT void JNICALL Java_org_pednav_Engine_nativeSetStart(JNIEnv *env, jclass cls, jlong handle, jdouble x,
                                                             jdouble y, jdouble z, jdouble heading_deg) {
    pn_engine_t *engine = engine_of(env, handle);
    const double pos_enu_m[3] = {x, y, z};
    pn_error_t err;
    (void)cls;
    if (!engine) return;
    init_error(&err);
    check_status(env, pn_engine_set_start(engine, pos_enu_m, heading_deg, &err), &err);
}

/* --------------------------------------------------------------- output */

/* Pops the oldest POSITION, STRIDE or STEP into the scratch arrays and
 * returns its record type, or 0 when the queue is empty. Other record types
 * (only present if an output mask asked for them) are skipped. */
JNIEXPORT jint JNICALL Java_org_pednav_Engine_nativePoll(JNIEnv *env, jclass cls, jlong handle, jlongArray longs,
                                                         jdoubleArray doubles) {
    pn_engine_t *engine = engine_of(env, handle);
    jlong l[PNJ_POLL_LONGS];
    jdouble d[PNJ_POLL_DOUBLES];
    pn_output_t out;
    int i;
    (void)cls;
    if (!engine) return 0;
    if (!longs || !doubles || (*env)->GetArrayLength(env, longs) < PNJ_POLL_LONGS ||
        (*env)->GetArrayLength(env, doubles) < PNJ_POLL_DOUBLES) {
        throw_java(env, "java/lang/IllegalArgumentException", "poll scratch arrays too small");
        return 0;
    }
    for (;;) {
        const pn_status_t status = pn_engine_poll(engine, &out);
        if (status == PN_NO_DATA) return 0;
        if (PN_FAILED(status)) {
            pn_error_t err;
            init_error(&err);
            err.code = status;
            throw_pednav(env, status, &err);
            return 0;
        }
        if (out.header.type == PN_REC_POSITION || out.header.type == PN_REC_STRIDE ||
            out.header.type == PN_REC_STEP)
            break;
    }
    memset(l, 0, sizeof l);
    memset(d, 0, sizeof d);
    l[0] = (jlong)out.header.t_ns;
    l[1] = (jlong)out.header.source_id;
    l[2] = (jlong)out.header.flags;
    switch (out.header.type) {
        case PN_REC_POSITION: {
            const pn_position_t *p = &out.position;
            for (i = 0; i < 3; ++i) d[i] = p->pos_enu_m[i];
            for (i = 0; i < 3; ++i) d[3 + i] = p->vel_enu_mps[i];
            for (i = 0; i < 9; ++i) d[6 + i] = p->cov_enu_m2[i];
            d[15] = p->heading_rad;
            l[4] = p->floor;
            l[5] = p->source;
            break;
        }
        case PN_REC_STRIDE: {
            const pn_stride_t *s = &out.stride;
            l[3] = (jlong)s->t_start_ns;
            l[5] = s->stride_class;
            l[6] = s->index;
            for (i = 0; i < 3; ++i) d[i] = s->displacement_enu_m[i];
            d[3] = s->length_m;
            d[4] = s->heading_change_rad;
            for (i = 0; i < 9; ++i) d[5 + i] = s->cov_displacement_m2[i];
            break;
        }
        default: { /* PN_REC_STEP */
            const pn_step_t *s = &out.step;
            l[3] = (jlong)s->t_start_ns;
            d[0] = s->accel_peak_to_peak_mps2;
            d[1] = s->frequency_hz;
            break;
        }
    }
    (*env)->SetLongArrayRegion(env, longs, 0, PNJ_POLL_LONGS, l);
    (*env)->SetDoubleArrayRegion(env, doubles, 0, PNJ_POLL_DOUBLES, d);
    return (jint)out.header.type;
}

JNIEXPORT jlong JNICALL Java_org_pednav_Engine_nativeLatencyNs(JNIEnv *env, jclass cls, jlong handle) {
    pn_engine_t *engine = engine_of(env, handle);
    (void)cls;
    return engine ? (jlong)pn_engine_latency_ns(engine) : 0;
}

/* The describe JSON as UTF-8 bytes (two-call size idiom). */
JNIEXPORT jbyteArray JNICALL Java_org_pednav_Engine_nativeDescribe(JNIEnv *env, jclass cls, jlong handle) {
    pn_engine_t *engine = engine_of(env, handle);
    char small[1024];
    char *buffer = small;
    size_t capacity = sizeof small, size = 0;
    jbyteArray result = NULL;
    int attempt;
    (void)cls;
    if (!engine) return NULL;
    for (attempt = 0; attempt < 4; ++attempt) {
        const pn_status_t status = pn_engine_describe(engine, buffer, capacity, &size);
        if (status == PN_OK) {
            result = utf8_bytes(env, buffer, capacity);
            break;
        }
        if (status != PN_E_INVALID_ARGUMENT || size <= capacity) {
            pn_error_t err;
            init_error(&err);
            err.code = status;
            strcpy(err.where, "describe");
            strcpy(err.message, "the engine could not describe itself");
            throw_pednav(env, PN_FAILED(status) ? status : PN_E_INTERNAL, &err);
            break;
        }
        if (buffer != small) free(buffer);
        capacity = size;
        buffer = (char *)malloc(capacity);
        if (!buffer) {
            throw_java(env, "java/lang/OutOfMemoryError", "pednav: no memory for describe");
            return NULL;
        }
    }
    if (!result && !(*env)->ExceptionCheck(env))
        throw_java(env, "java/lang/IllegalStateException", "describe kept growing between calls");
    if (buffer != small) free(buffer);
    return result;
}

/* -------------------------------------------------------------- library */

JNIEXPORT jint JNICALL Java_org_pednav_Engine_nativeAbiVersion(JNIEnv *env, jclass cls) {
    (void)env;
    (void)cls;
    return (jint)pn_abi_version();
}

JNIEXPORT jbyteArray JNICALL Java_org_pednav_Engine_nativeVersion(JNIEnv *env, jclass cls) {
    const char *v = pn_version_string();
    (void)cls;
    return utf8_bytes(env, v, v ? strlen(v) : 0);
}
