/* SPDX-License-Identifier: Apache-2.0 */
/*
 * Internals shared by the JNI glue's files (pednav_jni.c: load, create,
 * destroy, describe, the log callback; pnj_push.c; pnj_poll.c;
 * pnj_settings.c). Plain C over jni.h and pn_engine.h only.
 */
#ifndef PEDNAV_JNI_COMMON_H
#define PEDNAV_JNI_COMMON_H

#include <stdint.h>

#include <jni.h>
#include <pednav/pn_engine.h>

/* What a Java handle (Engine.handle, a long) points at. */
typedef struct pnj_engine_t {
    pn_engine_t *engine;
    /* Weak global reference to the engine's org.pednav.LogSink, or NULL. Weak,
     * so that a listener holding its Engine does not keep it alive through a
     * GC root; the Engine holds the sink strongly while it is in use. */
    jweak log_sink;
} pnj_engine_t;

/* Throws `class_name` (e.g. "java/lang/IllegalArgumentException") unless an
 * exception is already pending. */
void pnj_throw_java(JNIEnv *env, const char *class_name, const char *message);
/* Throws org.pednav.PednavException from a failed status and its error. */
void pnj_throw_pednav(JNIEnv *env, pn_status_t status, const pn_error_t *err);
/* Throws PednavException with the given where and message (calls without a pn_error_t). */
void pnj_throw_status(JNIEnv *env, pn_status_t status, const char *where, const char *message);
/* A byte[] holding at most `max` bytes of `text`, up to its first NUL. */
jbyteArray pnj_utf8_bytes(JNIEnv *env, const char *text, size_t max);
/* NUL-terminated malloc'ed copy of a byte[] (free it); NULL with an exception pending. */
char *pnj_copy_bytes(JNIEnv *env, jbyteArray bytes, size_t *len);

/* Zeroed error with struct_size set. */
void pnj_init_error(pn_error_t *err);
/* The engine behind a handle, or NULL with IllegalStateException thrown. */
pn_engine_t *pnj_engine_of(JNIEnv *env, jlong handle);
/* Throws when `status` is a failure. */
void pnj_check(JNIEnv *env, pn_status_t status, const pn_error_t *err);

/* The start of a direct ByteBuffer holding `bytes` bytes aligned to 8, or NULL
 * with IllegalArgumentException thrown (`what` names the buffer). */
unsigned char *pnj_direct_buffer(JNIEnv *env, jobject buffer, jlong bytes, const char *what);

#endif /* PEDNAV_JNI_COMMON_H */
