/* SPDX-License-Identifier: Apache-2.0 */
/*
 * pednav C API for the engine's readers of recordings (docs/formats.md).
 *
 * Opens a recording in any format the engine reads (detected, or named), and
 * hands out its streams as arrays of engine records (SI units, the sensor's
 * axes, t_ns from the file's own time origin), the ground truth a file carries,
 * and the reader's description: the format detected, each stream's rate and
 * units (found and converted), the notes and the issues it read past. Language
 * bindings read files through this instead of a reader of their own, so a
 * recording is read the same way by `pednav run`, an app and a script.
 *
 * Threading tags as in pn_engine.h: pn_recording_open is [thread-safe]; the
 * getters only read and are [any thread] on one recording; pn_recording_destroy
 * is [exclusive]. Different recordings are independent.
 *
 * Ownership. The recording owns every array and text it hands out: they stay
 * valid until pn_recording_destroy. Text goes into caller buffers with the
 * two-call size idiom of pn_engine_describe. Every function accepts err == NULL.
 */
#ifndef PEDNAV_PN_IO_H
#define PEDNAV_PN_IO_H

#include <stddef.h>
#include <stdint.h>

#include "pn_engine.h"
#include "pn_types.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct pn_recording_t pn_recording_t; /* opaque */

/* A ground-truth point of the recording (e.g. an IPIN POSI line), in local ENU
 * metres (lat/lon points around the "truth_origin" of the description). */
typedef struct pn_truth_point_t {
    double t_s;
    double pos_enu_m[3];
    int32_t floor;
    int32_t has_z; /* 1 when pos_enu_m[2] is known */
} pn_truth_point_t;

/* [thread-safe] Reads the recording at `path` (a file, or for two-file formats
 * the folder or either file). format: "auto" (or NULL) to detect it, or a name
 * from pn_recording_formats. options_json (NULL or "" = none): a JSON object
 * with "column_map" (the map of format "column-map", docs/formats.md), "gap_s"
 * (intervals reported as gaps, default 1) and "max_issues" (issues listed,
 * default 200); another key is refused with PN_E_INVALID_ARGUMENT, err.where
 * naming it ("/gap_x"). A file that cannot be read (missing, empty, binary, an
 * unknown format, no accelerometer and gyroscope) gives PN_E_BAD_INPUT with
 * err.where = "path:line" (just the path when no line is at fault), err.detail
 * = the line (0 = the whole file) and err.message = the reason; *recording is
 * then NULL. */
PN_API pn_status_t pn_recording_open(const char *path, const char *format, const char *options_json,
                                     pn_recording_t **recording, pn_error_t *err);
/* [exclusive] NULL-safe. Frees the recording and everything it handed out. */
PN_API void pn_recording_destroy(pn_recording_t *recording);

/* [any thread] The records of one input stream, in time order: type
 * PN_REC_IMU, PN_REC_MAG, PN_REC_BARO or PN_REC_GNSS (else
 * PN_E_INVALID_ARGUMENT). *records points at *count records laid out
 * *stride_bytes apart (NULL and 0 when the stream is empty). */
PN_API pn_status_t pn_recording_stream(const pn_recording_t *recording, pn_record_type_t type,
                                       const void **records, size_t *count, size_t *stride_bytes);
/* [any thread] Every input record in time order, at equal t_ns IMU, MAG, BARO,
 * GNSS: the order `pednav run` pushes them in (give them to
 * pn_engine_push_records). */
PN_API pn_status_t pn_recording_merged(const pn_recording_t *recording, const pn_record_header_t *const **records,
                                       size_t *count);
/* [any thread] The ground truth the file carries (none: NULL and 0). */
PN_API pn_status_t pn_recording_truth(const pn_recording_t *recording, const pn_truth_point_t **points,
                                      size_t *count);
/* [any thread] JSON of the recording, the one of `pednav inspect --json`
 * (docs/formats.md): path, format, axes, record counts, streams (rate,
 * units_found, units_converted, gaps, bad_rows), truth_origin, issues (line,
 * message), issues_not_listed, notes, plus "truth_labels" (one per truth
 * point). Two-call size idiom: *size is the full size including the NUL;
 * PN_E_INVALID_ARGUMENT when `capacity` is too small. */
PN_API pn_status_t pn_recording_describe(const pn_recording_t *recording, char *buffer, size_t capacity,
                                         size_t *size);
/* [thread-safe] JSON array of the format names pn_recording_open takes
 * besides "auto". Same size idiom. */
PN_API pn_status_t pn_recording_formats(char *buffer, size_t capacity, size_t *size);

/* [thread-safe] The writers of `pednav run --output` and `--steps`
 * (docs/formats.md): positions as a track CSV (t,x,y,z,heading_deg,floor,
 * cov_xx,cov_xy,cov_yy,cov_zz) and strides as a steps CSV, byte for byte what
 * the CLI writes for the same records, which `pednav eval` reads. A file that
 * cannot be written gives PN_E_IO with err.where = the path. */
PN_API pn_status_t pn_write_track_csv(const char *path, const pn_position_t *positions, size_t count,
                                      pn_error_t *err);
PN_API pn_status_t pn_write_steps_csv(const char *path, const pn_stride_t *strides, size_t count,
                                      pn_error_t *err);

#ifdef __cplusplus
}
#endif

#endif /* PEDNAV_PN_IO_H */
