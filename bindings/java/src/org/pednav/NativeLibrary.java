// SPDX-License-Identifier: Apache-2.0
package org.pednav;

/**
 * Loads libpednav_jni (which links libpednav). By default through
 * {@code System.loadLibrary("pednav_jni")}, i.e. from java.library.path (or an
 * Android app's nativeLibraryDir); the system property
 * {@code pednav.jni.library} may name the file instead.
 */
final class NativeLibrary {
    private static boolean loaded;

    private NativeLibrary() {}

    static synchronized void load() {
        if (loaded) return;
        String path = System.getProperty("pednav.jni.library");
        if (path != null && !path.isEmpty()) {
            System.load(path);
        } else {
            System.loadLibrary("pednav_jni");
        }
        loaded = true;
    }
}
