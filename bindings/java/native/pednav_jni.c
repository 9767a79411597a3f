/* SPDX-License-Identifier: Apache-2.0 */
/*
 * JNI glue between org.pednav.Engine and the app-facing C API (pn_engine.h):
 * loading, errors, create and destroy, the log callback, describe, versions.
 * Pushes are in pnj_push.c, polls in pnj_poll.c, settings in pnj_settings.c.
 *
 * Only the C header is used, so the same files build for desktop JVMs and
 * with the Android NDK. Rules kept throughout:
 *   - no Java exception is left pending across a call into the engine;
 *   - text from the engine (error fields, describe, log lines) crosses as
 *     UTF-8 bytes and is decoded on the Java side (NewStringUTF expects
 *     modified UTF-8);
 *   - the engine never sees a Java array: samples are copied into native
 *     buffers first, or read from direct ByteBuffers, so no critical section
 *     is held while the engine runs;
 *   - every failure becomes a Java exception, never an abort.
 */
#include <stdlib.h>
#include <string.h>

#include "pnj_common.h"

static JavaVM *g_vm;
static jclass g_pednav_exception; /* org.pednav.PednavException (global ref) */
static jmethodID g_from_native;   /* PednavException.fromNative(int, byte[], byte[], byte[], int) */
static jclass g_log_sink;         /* org.pednav.LogSink (global ref) */
static jmethodID g_deliver;       /* LogSink.deliver(LogSink, int, byte[], byte[]) */

/* Native engines created and not yet destroyed (Engine.liveNativeEngines, for tests). */
static long g_live_engines;

static jclass global_class(JNIEnv *env, const char *name) {
    jclass local = (*env)->FindClass(env, name);
    jclass global;
    if (!local) return NULL;
    global = (jclass)(*env)->NewGlobalRef(env, local);
    (*env)->DeleteLocalRef(env, local);
    return global;
}

JNIEXPORT jint JNICALL JNI_OnLoad(JavaVM *vm, void *reserved) {
    JNIEnv *env = NULL;
    (void)reserved;
    g_vm = vm;
    if ((*vm)->GetEnv(vm, (void **)&env, JNI_VERSION_1_6) != JNI_OK) return JNI_ERR;
    /* Looked up here: on Android only JNI_OnLoad runs with the app's class loader. */
    g_pednav_exception = global_class(env, "org/pednav/PednavException");
    g_log_sink = global_class(env, "org/pednav/LogSink");
    if (!g_pednav_exception || !g_log_sink) return JNI_ERR;
    g_from_native = (*env)->GetStaticMethodID(env, g_pednav_exception, "fromNative",
                                              "(I[B[B[BI)Lorg/pednav/PednavException;");
    g_deliver = (*env)->GetStaticMethodID(env, g_log_sink, "deliver", "(Lorg/pednav/LogSink;I[B[B)V");
    if (!g_from_native || !g_deliver) return JNI_ERR;
    return JNI_VERSION_1_6;
}

JNIEXPORT void JNICALL JNI_OnUnload(JavaVM *vm, void *reserved) {
    JNIEnv *env = NULL;
    (void)reserved;
    if ((*vm)->GetEnv(vm, (void **)&env, JNI_VERSION_1_6) != JNI_OK) return;
    if (g_pednav_exception) (*env)->DeleteGlobalRef(env, g_pednav_exception);
    if (g_log_sink) (*env)->DeleteGlobalRef(env, g_log_sink);
    g_pednav_exception = NULL;
    g_log_sink = NULL;
}

/* ---------------------------------------------------------------- errors */

void pnj_throw_java(JNIEnv *env, const char *class_name, const char *message) {
    jclass cls;
    if ((*env)->ExceptionCheck(env)) return;
    cls = (*env)->FindClass(env, class_name);
    if (cls) {
        (*env)->ThrowNew(env, cls, message);
        (*env)->DeleteLocalRef(env, cls);
    }
}

jbyteArray pnj_utf8_bytes(JNIEnv *env, const char *text, size_t max) {
    size_t n = 0;
    jbyteArray out;
    if (!text) text = "";
    while (n < max && text[n] != '\0') ++n;
    out = (*env)->NewByteArray(env, (jsize)n);
    if (out && n) (*env)->SetByteArrayRegion(env, out, 0, (jsize)n, (const jbyte *)text);
    return out;
}

void pnj_throw_pednav(JNIEnv *env, pn_status_t status, const pn_error_t *err) {
    const char *name = pn_status_name(status);
    jbyteArray jname, jwhere, jmessage;
    jthrowable exc;
    if ((*env)->ExceptionCheck(env)) return;
    jname = pnj_utf8_bytes(env, name, strlen(name));
    jwhere = pnj_utf8_bytes(env, err->where, sizeof err->where);
    jmessage = pnj_utf8_bytes(env, err->message, sizeof err->message);
    if (!jname || !jwhere || !jmessage) return; /* OutOfMemoryError pending */
    exc = (jthrowable)(*env)->CallStaticObjectMethod(env, g_pednav_exception, g_from_native, (jint)status,
                                                     jname, jwhere, jmessage, (jint)err->detail);
    if (exc && !(*env)->ExceptionCheck(env)) (*env)->Throw(env, exc);
}

void pnj_init_error(pn_error_t *err) {
    memset(err, 0, sizeof *err);
    err->struct_size = sizeof *err;
}

void pnj_throw_status(JNIEnv *env, pn_status_t status, const char *where, const char *message) {
    pn_error_t err;
    pnj_init_error(&err);
    err.code = status;
    strncpy(err.where, where, sizeof err.where - 1);
    strncpy(err.message, message, sizeof err.message - 1);
    pnj_throw_pednav(env, status, &err);
}

pn_engine_t *pnj_engine_of(JNIEnv *env, jlong handle) {
    const pnj_engine_t *h = (const pnj_engine_t *)(intptr_t)handle;
    if (!h || !h->engine) {
        pnj_throw_java(env, "java/lang/IllegalStateException", "the engine is closed");
        return NULL;
    }
    return h->engine;
}

void pnj_check(JNIEnv *env, pn_status_t status, const pn_error_t *err) {
    if (PN_FAILED(status)) pnj_throw_pednav(env, status, err);
}

char *pnj_copy_bytes(JNIEnv *env, jbyteArray bytes, size_t *len) {
    jsize n;
    char *out;
    if (!bytes) {
        pnj_throw_java(env, "java/lang/NullPointerException", "null byte array");
        return NULL;
    }
    n = (*env)->GetArrayLength(env, bytes);
    out = (char *)malloc((size_t)n + 1);
    if (!out) {
        pnj_throw_java(env, "java/lang/OutOfMemoryError", "pednav: no memory for a string copy");
        return NULL;
    }
    (*env)->GetByteArrayRegion(env, bytes, 0, n, (jbyte *)out);
    out[n] = '\0';
    if (len) *len = (size_t)n;
    return out;
}

unsigned char *pnj_direct_buffer(JNIEnv *env, jobject buffer, jlong bytes, const char *what) {
    unsigned char *base;
    jlong capacity;
    if (!buffer) {
        pnj_throw_java(env, "java/lang/NullPointerException", what);
        return NULL;
    }
    base = (unsigned char *)(*env)->GetDirectBufferAddress(env, buffer);
    capacity = (*env)->GetDirectBufferCapacity(env, buffer);
    if (!base || capacity < bytes || bytes < 0 || ((uintptr_t)base & 7u) != 0) {
        pnj_throw_java(env, "java/lang/IllegalArgumentException", what);
        return NULL;
    }
    return base;
}

/* ------------------------------------------------------------------ log */

/* pn_log_fn: hands the line to LogSink.deliver on the calling thread, which
 * is inside a JNI call of this engine (create, a push, flush, reset, destroy)
 * and so attached. Deliver catches what the listener throws; anything still
 * pending here (an OutOfMemoryError making the arrays) is cleared, so the
 * engine's call goes on and its own result is what Java sees. */
static void deliver_log(void *user, int32_t level, const char *source, const char *msg) {
    const pnj_engine_t *h = (const pnj_engine_t *)user;
    JNIEnv *env = NULL;
    jobject sink;
    if (!h || !h->log_sink || !g_vm) return;
    if ((*g_vm)->GetEnv(g_vm, (void **)&env, JNI_VERSION_1_6) != JNI_OK) return; /* not a JVM thread */
    if ((*env)->ExceptionCheck(env)) return; /* never call Java with an exception pending */
    if ((*env)->PushLocalFrame(env, 4) != 0) {
        (*env)->ExceptionClear(env);
        return;
    }
    sink = (*env)->NewLocalRef(env, h->log_sink);
    if (sink) {
        jbyteArray jsource = pnj_utf8_bytes(env, source, source ? strlen(source) : 0);
        jbyteArray jmsg = jsource ? pnj_utf8_bytes(env, msg, msg ? strlen(msg) : 0) : NULL;
        if (jmsg) (*env)->CallStaticVoidMethod(env, g_log_sink, g_deliver, sink, (jint)level, jsource, jmsg);
    }
    if ((*env)->ExceptionCheck(env)) (*env)->ExceptionClear(env);
    (*env)->PopLocalFrame(env, NULL);
}

/* --------------------------------------------------------------- create */

static void free_handle(JNIEnv *env, pnj_engine_t *h) {
    if (!h) return;
    if (h->log_sink) (*env)->DeleteWeakGlobalRef(env, h->log_sink);
    free(h);
}

JNIEXPORT jlong JNICALL Java_org_pednav_Engine_nativeCreate(JNIEnv *env, jclass cls, jbyteArray config_utf8,
                                                            jobjectArray plugin_dirs_utf8, jobject log_sink) {
    pn_engine_create_info_t info;
    pn_error_t err;
    pnj_engine_t *h;
    pn_status_t status;
    char *config;
    char **dirs = NULL;
    size_t config_len = 0;
    jsize dir_count = 0, i;
    (void)cls;

    h = (pnj_engine_t *)calloc(1, sizeof *h);
    if (!h) {
        pnj_throw_java(env, "java/lang/OutOfMemoryError", "pednav: no memory for an engine handle");
        return 0;
    }
    if (log_sink) {
        h->log_sink = (*env)->NewWeakGlobalRef(env, log_sink);
        if (!h->log_sink) {
            free(h);
            return 0; /* OutOfMemoryError pending */
        }
    }
    config = pnj_copy_bytes(env, config_utf8, &config_len);
    if (plugin_dirs_utf8) dir_count = (*env)->GetArrayLength(env, plugin_dirs_utf8);
    if (config && dir_count > 0) {
        dirs = (char **)calloc((size_t)dir_count, sizeof *dirs);
        if (!dirs)
            pnj_throw_java(env, "java/lang/OutOfMemoryError", "pednav: no memory for plugin directories");
    }
    for (i = 0; dirs && i < dir_count; ++i) {
        jbyteArray dir = (jbyteArray)(*env)->GetObjectArrayElement(env, plugin_dirs_utf8, i);
        dirs[i] = pnj_copy_bytes(env, dir, NULL);
        if (dir) (*env)->DeleteLocalRef(env, dir);
        if (!dirs[i]) break;
    }

    if (config && !(*env)->ExceptionCheck(env)) {
        memset(&info, 0, sizeof info);
        info.abi_version = PN_ABI_VERSION;
        info.struct_size = sizeof info;
        info.config_json = config;
        info.config_len = config_len;
        info.plugin_dirs = (const char *const *)dirs;
        info.plugin_dir_count = (uint32_t)dir_count;
        if (h->log_sink) {
            info.log = deliver_log;
            info.log_user = h;
        }
        pnj_init_error(&err);
        status = pn_engine_create(&info, &h->engine, &err);
        if (PN_FAILED(status) || !h->engine) {
            if (!PN_FAILED(status)) status = PN_E_INTERNAL;
            pnj_throw_pednav(env, status, &err);
            h->engine = NULL;
        }
    }

    for (i = 0; dirs && i < dir_count; ++i) free(dirs[i]);
    free(dirs);
    free(config);
    if (!h->engine) {
        free_handle(env, h);
        return 0;
    }
    __atomic_add_fetch(&g_live_engines, 1, __ATOMIC_SEQ_CST);
    return (jlong)(intptr_t)h;
}

/* Called once per engine: by close() or by the Cleaner. Lines the engine logs
 * while its plugins are destroyed still reach the listener if it is alive. */
JNIEXPORT void JNICALL Java_org_pednav_Engine_nativeDestroy(JNIEnv *env, jclass cls, jlong handle) {
    pnj_engine_t *h = (pnj_engine_t *)(intptr_t)handle;
    (void)cls;
    if (!h) return;
    pn_engine_destroy(h->engine);
    h->engine = NULL;
    free_handle(env, h);
    __atomic_sub_fetch(&g_live_engines, 1, __ATOMIC_SEQ_CST);
}

JNIEXPORT jlong JNICALL Java_org_pednav_Engine_nativeLiveEngines(JNIEnv *env, jclass cls) {
    (void)env;
    (void)cls;
    return (jlong)__atomic_load_n(&g_live_engines, __ATOMIC_SEQ_CST);
}

/* ------------------------------------------------------------- describe */

JNIEXPORT jlong JNICALL Java_org_pednav_Engine_nativeLatencyNs(JNIEnv *env, jclass cls, jlong handle) {
    pn_engine_t *engine = pnj_engine_of(env, handle);
    (void)cls;
    return engine ? (jlong)pn_engine_latency_ns(engine) : 0;
}

/* The describe JSON as UTF-8 bytes (two-call size idiom). */
JNIEXPORT jbyteArray JNICALL Java_org_pednav_Engine_nativeDescribe(JNIEnv *env, jclass cls, jlong handle) {
    pn_engine_t *engine = pnj_engine_of(env, handle);
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
            result = pnj_utf8_bytes(env, buffer, capacity);
            break;
        }
        if (status != PN_E_INVALID_ARGUMENT || size <= capacity) {
            pnj_throw_status(env, PN_FAILED(status) ? status : PN_E_INTERNAL, "describe",
                             "the engine could not describe itself");
            break;
        }
        if (buffer != small) free(buffer);
        capacity = size;
        buffer = (char *)malloc(capacity);
        if (!buffer) {
            pnj_throw_java(env, "java/lang/OutOfMemoryError", "pednav: no memory for describe");
            return NULL;
        }
    }
    if (!result && !(*env)->ExceptionCheck(env))
        pnj_throw_java(env, "java/lang/IllegalStateException", "describe kept growing between calls");
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
    return pnj_utf8_bytes(env, v, v ? strlen(v) : 0);
}
