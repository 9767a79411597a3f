// SPDX-License-Identifier: Apache-2.0
package org.pednav;

import java.nio.charset.StandardCharsets;

/**
 * A failure reported by the engine: the status of the C API call and the
 * fields of its {@code pn_error_t}.
 *
 * <p>{@link #statusName()} is the C name of the status ("PN_E_INVALID_CONFIG"),
 * {@link #where()} a JSON pointer into the config, a plugin file, an instance
 * name such as "foot/position_filter", or "input" for a rejected sample, and
 * {@link #detail()} a producer-specific number (for a rejected sample: its
 * index in the pushed array).
 */
public final class PednavException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    /** {@code PN_E_INVALID_ARGUMENT}. */
    public static final int INVALID_ARGUMENT = -1;
    /** {@code PN_E_INVALID_CONFIG}: {@link #where()} names the config key. */
    public static final int INVALID_CONFIG = -2;
    /** {@code PN_E_UNSUPPORTED}. */
    public static final int UNSUPPORTED = -3;
    /** {@code PN_E_ABI_MISMATCH}. */
    public static final int ABI_MISMATCH = -4;
    /** {@code PN_E_NOT_FOUND}. */
    public static final int NOT_FOUND = -5;
    /** {@code PN_E_BAD_STATE}. */
    public static final int BAD_STATE = -6;
    /** {@code PN_E_OUT_OF_ORDER}: time went backwards or repeated. */
    public static final int OUT_OF_ORDER = -7;
    /** {@code PN_E_NUMERIC}: non-finite input or output. */
    public static final int NUMERIC = -8;
    /** {@code PN_E_OUT_OF_MEMORY}. */
    public static final int OUT_OF_MEMORY = -9;
    /** {@code PN_E_IO}. */
    public static final int IO = -10;
    /** {@code PN_E_INTERNAL}: a plugin threw or broke its contract. */
    public static final int INTERNAL = -11;
    /** {@code PN_E_BAD_INPUT}: malformed sample. */
    public static final int BAD_INPUT = -12;

    private final int status;
    private final String statusName;
    private final String where;
    private final String errorMessage;
    private final int detail;

    public PednavException(int status, String statusName, String where, String errorMessage, int detail) {
        super(format(statusName, where, errorMessage));
        this.status = status;
        this.statusName = statusName;
        this.where = where;
        this.errorMessage = errorMessage;
        this.detail = detail;
    }

    /** Called by the JNI glue; the text fields arrive as UTF-8 bytes. */
    static PednavException fromNative(int status, byte[] statusName, byte[] where, byte[] message, int detail) {
        return new PednavException(status, utf8(statusName), utf8(where), utf8(message), detail);
    }

    /** The {@code pn_status_t} code (negative). */
    public int status() {
        return status;
    }

    /** The C name of the status, e.g. "PN_E_NUMERIC". */
    public String statusName() {
        return statusName;
    }

    /** {@code pn_error_t.where}; empty when the engine gave none. */
    public String where() {
        return where;
    }

    /** {@code pn_error_t.message}: the engine's sentence alone. */
    public String errorMessage() {
        return errorMessage;
    }

    /** {@code pn_error_t.detail}. */
    public int detail() {
        return detail;
    }

    private static String utf8(byte[] b) {
        return b == null ? "" : new String(b, StandardCharsets.UTF_8);
    }

    private static String format(String statusName, String where, String message) {
        StringBuilder sb = new StringBuilder(statusName);
        if (where != null && !where.isEmpty()) sb.append(" at ").append(where);
        if (message != null && !message.isEmpty()) sb.append(": ").append(message);
        return sb.toString();
    }
}
