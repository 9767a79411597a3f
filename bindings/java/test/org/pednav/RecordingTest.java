// SPDX-License-Identifier: Apache-2.0
package org.pednav;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;
import static org.pednav.TestSupport.assertSameOutputs;
import static org.pednav.TestSupport.firstPartyPluginDir;
import static org.pednav.TestSupport.ofType;

import java.io.IOException;
import java.math.BigDecimal;
import java.math.RoundingMode;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Real recordings through the foot preset (configs/foot.json) from Java give
 * the positions of the same run through the C API bit for bit
 * (test/native/reference_run.c, run by ctest before this test: it reads the
 * file with the engine's readers and writes the records and positions in
 * exact hex), and the CLI's figures: positions, distance, final position.
 */
class RecordingTest {
    /**
     * The records reference_run wrote, pushed through RecordBuffers of 1000
     * records, polling after each (the output queue holds 8192 records).
     */
    private static List<Output> pushBuffers(Engine e, List<String[]> records) {
        RecordBuffer b = new RecordBuffer(1000 * RecordBuffer.GNSS_RECORD_BYTES);
        List<Output> out = new ArrayList<>();
        for (String[] r : records) {
            if (b.remainingBytes() < RecordBuffer.GNSS_RECORD_BYTES) {
                e.push(b);
                b.clear();
                out.addAll(e.pollAll());
            }
            long t = Long.parseLong(r[1]);
            switch (r[0]) {
                case "imu" -> b.putImu(t, d(r[2]), d(r[3]), d(r[4]), d(r[5]), d(r[6]), d(r[7]));
                case "mag" -> b.putMag(t, d(r[2]), d(r[3]), d(r[4]));
                case "baro" -> b.putBaro(t, d(r[2]), d(r[3]));
                case "gnss" -> b.putGnss(t, d(r[2]), d(r[3]), d(r[4]), d(r[5]), d(r[6]));
                default -> fail("unknown record " + r[0]);
            }
        }
        e.push(b);
        e.flush();
        out.addAll(e.pollAll());
        return out;
    }

    /** The same records, one call per record, polling every 1000. */
    private static List<Output> pushOneByOne(Engine e, List<String[]> records) {
        List<Output> out = new ArrayList<>();
        for (int i = 0; i < records.size(); ++i) {
            if (i % 1000 == 999) out.addAll(e.pollAll());
            String[] r = records.get(i);
            long t = Long.parseLong(r[1]);
            switch (r[0]) {
                case "imu" -> e.pushImu(t, d(r[2]), d(r[3]), d(r[4]), d(r[5]), d(r[6]), d(r[7]));
                case "mag" -> e.pushMag(t, d(r[2]), d(r[3]), d(r[4]));
                case "baro" -> e.pushBaro(t, d(r[2]), d(r[3]));
                case "gnss" -> e.pushGnss(t, d(r[2]), d(r[3]), d(r[4]), d(r[5]), d(r[6]));
                default -> fail("unknown record " + r[0]);
            }
        }
        e.flush();
        out.addAll(e.pollAll());
        return out;
    }

    /** A C99 hex double ("0x1.8p+1"), as printf's %a writes it. */
    private static double d(String hex) {
        return Double.parseDouble(hex);
    }

    private static List<String[]> lines(Path p) throws IOException {
        assertTrue(Files.isRegularFile(p), "missing " + p + " (written by ctest's java.reference.* tests)");
        List<String[]> out = new ArrayList<>();
        for (String line : Files.readAllLines(p, StandardCharsets.US_ASCII)) out.add(line.split(" "));
        return out;
    }

    /** The %.Nf of C's printf: the exact binary value rounded half-even. */
    private static String fixed(double v, int digits) {
        String s = new BigDecimal(v).setScale(digits, RoundingMode.HALF_EVEN).toPlainString();
        return v < 0 && !s.startsWith("-") ? "-" + s : s; // printf keeps the sign of a negative rounded to zero
    }

    @ParameterizedTest
    @CsvSource({"koroglu35, koroglu-foot-gcp/SensorConnectData_35.csv, 40.0",
                "xio_short, xio-gait-ngimu/short_walk.csv, 15.0"})
    void footPresetGivesTheCApiPositionsBitForBitAndTheCliFigures(String name, String file, double minDistanceM)
            throws IOException, InterruptedException {
        Path ref = Path.of(System.getProperty("pednav.test.referenceDir"));
        List<String[]> records = lines(ref.resolve(name + "_inputs.txt"));
        List<String[]> expected = lines(ref.resolve(name + "_positions.txt"));
        String preset = Files.readString(Path.of(System.getProperty("pednav.test.footPreset")));

        List<Output> viaBuffers, viaCalls;
        try (Engine e = Engine.create(preset, firstPartyPluginDir())) {
            viaBuffers = pushBuffers(e, records);
        }
        try (Engine e = Engine.create(preset, firstPartyPluginDir())) {
            viaCalls = pushOneByOne(e, records);
        }
        assertSameOutputs(viaCalls, viaBuffers);

        List<Position> pos = ofType(viaBuffers, Position.class);
        assertEquals(expected.size(), pos.size(), "positions");
        for (int i = 0; i < pos.size(); ++i) {
            String[] x = expected.get(i);
            Position p = pos.get(i);
            assertEquals(Long.parseLong(x[0]), p.tNs(), "t_ns of position " + i);
            for (int k = 0; k < 3; ++k)
                assertEquals(Double.doubleToRawLongBits(d(x[1 + k])), Double.doubleToRawLongBits(p.posEnuM()[k]),
                        "axis " + k + " of position " + i);
            assertEquals(Double.doubleToRawLongBits(d(x[4])), Double.doubleToRawLongBits(p.headingRad()),
                    "heading of position " + i);
        }

        double distanceM = 0.0; // the CLI's track length: horizontal steps between positions
        for (int i = 1; i < pos.size(); ++i)
            distanceM += Math.hypot(pos.get(i).east() - pos.get(i - 1).east(), pos.get(i).north() - pos.get(i - 1).north());
        Position last = pos.get(pos.size() - 1);
        System.out.println(name + ": " + records.size() + " records, " + pos.size() + " positions, "
                + ofType(viaBuffers, Stride.class).size() + " strides, distance " + fixed(distanceM, 2)
                + " m, final (" + fixed(last.east(), 3) + ", " + fixed(last.north(), 3) + ", " + fixed(last.up(), 3) + ") m");
        assertTrue(distanceM > minDistanceM, "distance " + distanceM);

        // The CLI on the same file: its summary and the last row of its track.
        Path work = Files.createDirectories(Path.of(System.getProperty("pednav.test.workDir")));
        Path track = work.resolve(name + "_cli_track.csv");
        Process cli = new ProcessBuilder(System.getProperty("pednav.test.cli"), "run", "--mount", "foot", "--input",
                Path.of(System.getProperty("pednav.test.sharedData"), file).toString(), "--output", track.toString())
                .redirectErrorStream(true).start();
        String out = new String(cli.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(0, cli.waitFor(), out);
        Matcher m = Pattern.compile("positions (\\d+), steps (\\d+), distance ([0-9.]+) m").matcher(out);
        assertTrue(m.find(), out);
        assertEquals(pos.size(), Integer.parseInt(m.group(1)));
        assertEquals(ofType(viaBuffers, Stride.class).size(), Integer.parseInt(m.group(2)));
        assertEquals(fixed(distanceM, 2), m.group(3));
        Matcher f = Pattern.compile("final position x (-?[0-9.]+) m, y (-?[0-9.]+) m, z (-?[0-9.]+) m").matcher(out);
        assertTrue(f.find(), out);
        assertEquals(fixed(last.east(), 3), f.group(1));
        assertEquals(fixed(last.north(), 3), f.group(2));
        assertEquals(fixed(last.up(), 3), f.group(3));
        List<String> rows = Files.readAllLines(track);
        assertEquals(pos.size() + 1, rows.size());
        String[] lastRow = rows.get(rows.size() - 1).split(",");
        assertEquals(fixed(last.east(), 6), lastRow[1]);
        assertEquals(fixed(last.north(), 6), lastRow[2]);
        assertEquals(fixed(last.up(), 6), lastRow[3]);
    }
}
