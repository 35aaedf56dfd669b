package org.robotrun.grade;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.zip.Deflater;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Submissions made to break the grader: each gets a clear failure within the limits, and the
 * others around it are still graded.
 */
class HostileSubmissionTest {
  private static final Path TASK = Path.of("scenarios/tasks/pick-and-place.task.json");
  private static final Path REFERENCE = Path.of("tests/resources/grade/reference");
  private static TaskLoad.Loaded task;
  private static Grader grader;

  @TempDir Path dir;

  @BeforeAll
  static void loadTask() {
    task = (TaskLoad.Loaded) TaskReader.read(TASK);
    grader = new Grader(task.task(), task.scenario());
  }

  private static String fatal(Path p) {
    try (Submission s = new SubmissionLoader().load(p)) {
      assertThat(s.fatal()).as("refused").isPresent();
      return s.fatal().get();
    }
  }

  private byte[] program(String name) throws Exception {
    return Files.readAllBytes(REFERENCE.resolve("programs/" + name + ".LS"));
  }

  @Test
  void zipSlipIsRefusedAndNothingIsWrittenOutside() throws Exception {
    Path zip = dir.resolve("slip.zip");
    Map<String, byte[]> e = new LinkedHashMap<>();
    e.put("programs/PICKPLACE.LS", program("PICKPLACE"));
    e.put("programs/../../../../../../tmp/robotrun-zip-slip.LS", "evil".getBytes(StandardCharsets.UTF_8));
    Files.write(zip, HandIns.rawZip(e));
    assertThat(fatal(zip)).isEqualTo(
        "the zip entry \"programs/../../../../../../tmp/robotrun-zip-slip.LS\" points outside the zip (\"..\")");
    assertThat(Path.of("/tmp/robotrun-zip-slip.LS")).doesNotExist();

    Files.write(zip, HandIns.rawZip(Map.of("/etc/robotrun.LS", new byte[1])));
    assertThat(fatal(zip)).contains("is not a relative path inside the zip");
    Files.write(zip, HandIns.rawZip(Map.of("C:\\x.LS", new byte[1])));
    assertThat(fatal(zip)).contains("is not a relative path inside the zip");
  }

  /**
   * A zip whose headers declare a 10 GB entry (ZIP64 sizes) and whose deflate data really
   * inflates to 64 MiB: 64 KiB on disk. The loader must stop at its per-entry limit while
   * inflating, whatever the headers say.
   */
  @Test
  void aZipBombDeclaringTenGigabytesStopsAtTheEntryLimit() throws Exception {
    byte[] zeros = new byte[1 << 20];
    ByteArrayOutputStream deflated = new ByteArrayOutputStream();
    Deflater d = new Deflater(9, true);
    byte[] buf = new byte[1 << 16];
    for (int i = 0; i < 64; i++) {
      d.setInput(zeros);
      while (!d.needsInput()) {
        deflated.write(buf, 0, d.deflate(buf));
      }
    }
    d.finish();
    while (!d.finished()) {
      deflated.write(buf, 0, d.deflate(buf));
    }
    d.end();
    Path zip = dir.resolve("bomb.zip");
    Files.write(zip, zip64Entry("programs/BOMB.LS", deflated.toByteArray(), 10L << 30));
    assertThat(Files.size(zip)).isLessThan(1 << 20);
    long t0 = System.nanoTime();
    assertThat(fatal(zip)).isEqualTo("\"programs/BOMB.LS\" unpacks to more than 16 MiB");
    assertThat((System.nanoTime() - t0) / 1e9).as("seconds").isLessThan(10);
  }

  @Test
  void manyEntriesEachBelowTheLimitStopAtTheTotal() throws Exception {
    Path zip = dir.resolve("wide.zip");
    try (OutputStream f = new java.io.BufferedOutputStream(Files.newOutputStream(zip), 1 << 16);
        ZipOutputStream z = new ZipOutputStream(f)) {
      byte[] big = new byte[3 << 20];
      for (int i = 0; i < 25; i++) {
        z.putNextEntry(new ZipEntry("programs/P" + i + ".LS"));
        z.write(big);
        z.closeEntry();
      }
    }
    assertThat(fatal(zip)).startsWith("the hand-in unpacks to more than 64 MiB (at \"programs/P21.LS\")");
  }

  @Test
  void aHundredThousandProgramsAreRefusedAtTheEntryLimit() throws Exception {
    Path zip = dir.resolve("many.zip");
    byte[] tiny = "/PROG X\n/MN\n/END\n".getBytes(StandardCharsets.UTF_8);
    Files.write(zip, storedZip(100_000, tiny));
    assertThat(Files.size(zip)).isGreaterThan(100_000L * 100);
    long t0 = System.nanoTime();
    assertThat(fatal(zip)).isEqualTo("the zip has more than 2000 entries");
    assertThat((System.nanoTime() - t0) / 1e9).as("seconds").isLessThan(10);
  }

  @Test
  void aFolderWithTooManyProgramsIsRefusedWithoutReadingThem() throws Exception {
    Path folder = Files.createDirectory(dir.resolve("many"));
    for (int i = 0; i < 11; i++) {
      Files.writeString(folder.resolve("P" + i + ".LS"), "x");
    }
    try (Submission s = new SubmissionLoader(new org.robotrun.io.HandInFiles.Limits(10, 1 << 20, 1 << 22)).load(folder)) {
      assertThat(s.fatal()).contains("the folder holds more than 10 files; a submission may hold at most 10");
    }
  }

  @Test
  void aNonUtf8NameIsRefused() throws Exception {
    Path zip = dir.resolve("latin1.zip");
    ByteArrayOutputStream out = new ByteArrayOutputStream();
    try (ZipOutputStream z = new ZipOutputStream(out, StandardCharsets.ISO_8859_1)) {
      z.putNextEntry(new ZipEntry("programs/PR\u00dcF.LS"));
      z.write(program("PICKPLACE"));
      z.closeEntry();
    }
    Files.write(zip, out.toByteArray());
    assertThat(fatal(zip)).isEqualTo(
        "entry 1 of the zip has a file name that is not UTF-8; make the zip again with RobotRun's Hand in");
  }

  @Test
  void notAZipAtAllIsAClearFailure() throws Exception {
    Path zip = dir.resolve("junk.zip");
    byte[] junk = new byte[4096];
    new Random(1).nextBytes(junk);
    Files.write(zip, junk);
    GradeResult r = Grading.gradeOne(grader, new SubmissionLoader(), zip, true);
    assertThat(r.score()).isZero();
    assertThat(r.checks()).allSatisfy(c -> assertThat(c.feedback()).startsWith("The submission could not be graded: "));
  }

  @Test
  void aBinaryOrHugeProgramFailsTheProgramsCheck() throws Exception {
    Map<String, byte[]> files = new LinkedHashMap<>();
    files.put("cell.json", Files.readAllBytes(REFERENCE.resolve("cell.json")));
    files.put("programs/PICKPLACE.LS", program("PICKPLACE"));
    byte[] binary = new byte[2000];
    new Random(2).nextBytes(binary);
    files.put("programs/BLOB.LS", binary);
    GradeResult r = Grading.gradeOne(grader, new SubmissionLoader(), HandIns.zip(files, "Eve", dir.resolve("bin.zip")), true);
    assertThat(HandIns.check(r, "Programs read").passed()).isFalse();
    assertThat(HandIns.check(r, "Programs read").feedback()).contains("programs/BLOB.LS:");
    assertThat(r.runs()).isEmpty();
  }

  @Test
  void anEndlessLoopStopsAtTheSimulatedTimeLimit() throws Exception {
    Path folder = Files.createDirectories(dir.resolve("loop/programs"));
    Files.writeString(folder.resolve("PICKPLACE.LS"), endlessLoop());
    Task t = task.task();
    Task shortTask = new Task(t.file(), t.title(), t.scenario(), t.program(), new Task.Limits(20, 30), t.variations(),
        t.checks());
    GradeResult r = Grading.gradeOne(new Grader(shortTask, task.scenario()), new SubmissionLoader(), folder, true);
    assertThat(HandIns.check(r, "Runs to the end").feedback()).startsWith(
        "the program stopped with alarm RUN-001 (PICKPLACE, ");
    assertThat(HandIns.check(r, "Runs to the end").feedback()).contains("time limit reached");
  }

  @Test
  void theWallClockLimitStopsASubmissionAndTheOthersAreStillGraded() throws Exception {
    Path loop = Files.createDirectories(dir.resolve("wall/programs"));
    Files.writeString(loop.resolve("PICKPLACE.LS"), endlessLoop());
    Task t = task.task();
    // Nominal checks only: the reference then needs one run, well inside the limit even on a busy machine.
    Task wallTask = new Task(t.file(), t.title(), t.scenario(), t.program(), new Task.Limits(3600, 1.5), t.variations(),
        t.checks().stream().filter(c -> c.meta().runs() == Check.Runs.NOMINAL).toList());
    Grader g = new Grader(wallTask, task.scenario());
    List<GradeResult> rs = Grading.gradeAll(g, new SubmissionLoader(),
        List.of(loop, REFERENCE, dir.resolve("missing.zip")), 2, true, r -> { });
    assertThat(HandIns.check(rs.get(0), "Runs to the end").feedback()).startsWith(
        "not run: nominal run: stopped after 1.5 s of wall-clock time (the grader's limit per submission)");
    assertThat(HandIns.check(rs.get(1), "Runs to the end").passed()).isTrue();
    assertThat(HandIns.check(rs.get(2), "Runs to the end").feedback())
        .startsWith("The submission could not be graded: no such file or folder\n");
  }

  /**
   * {@code count} stored entries programs/P0.LS... of {@code data}, with a central directory,
   * written directly (ZipOutputStream takes seconds for 100 000 entries).
   */
  private static byte[] storedZip(int count, byte[] data) {
    java.util.zip.CRC32 crc = new java.util.zip.CRC32();
    crc.update(data);
    int c = (int) crc.getValue();
    ByteBuffer local = ByteBuffer.allocate(count * (60 + data.length)).order(ByteOrder.LITTLE_ENDIAN);
    ByteBuffer central = ByteBuffer.allocate(count * 80 + 22).order(ByteOrder.LITTLE_ENDIAN);
    for (int i = 0; i < count; i++) {
      byte[] n = ("programs/P" + i + ".LS").getBytes(StandardCharsets.UTF_8);
      int offset = local.position();
      local.putInt(0x04034b50).putShort((short) 10).putShort((short) 0).putShort((short) 0).putInt(0).putInt(c)
          .putInt(data.length).putInt(data.length).putShort((short) n.length).putShort((short) 0).put(n).put(data);
      central.putInt(0x02014b50).putShort((short) 10).putShort((short) 10).putShort((short) 0).putShort((short) 0)
          .putInt(0).putInt(c).putInt(data.length).putInt(data.length).putShort((short) n.length).putShort((short) 0)
          .putShort((short) 0).putShort((short) 0).putShort((short) 0).putInt(0).putInt(offset).put(n);
    }
    int cdSize = central.position();
    // 100 000 entries need ZIP64 counts; a streaming reader never looks at them, 0xFFFF says "see ZIP64".
    central.putInt(0x06054b50).putShort((short) 0).putShort((short) 0).putShort((short) -1).putShort((short) -1)
        .putInt(cdSize).putInt(local.position()).putShort((short) 0);
    byte[] out = new byte[local.position() + central.position()];
    local.flip().get(out, 0, local.limit());
    central.flip().get(out, local.limit(), central.limit());
    return out;
  }

  /** PICKPLACE moving between HOME and PICK for ever. */
  private String endlessLoop() throws Exception {
    String ref = new String(program("PICKPLACE"), StandardCharsets.UTF_8);
    return ref.substring(0, ref.indexOf("/MN")) + "/MN\n   1:  UFRAME_NUM=1 ;\n   2:  UTOOL_NUM=1 ;\n   3:  LBL[5] ;\n"
        + "   4:J P[1:HOME] 100% FINE    ;\n   5:J P[2:PICK] 100% FINE    ;\n   6:  JMP LBL[5] ;\n"
        + ref.substring(ref.indexOf("/POS"));
  }

  /** One stored-as-deflated entry whose local and central headers declare {@code declared} bytes (ZIP64). */
  private static byte[] zip64Entry(String name, byte[] deflated, long declared) {
    byte[] n = name.getBytes(StandardCharsets.UTF_8);
    ByteBuffer b = ByteBuffer.allocate(200 + 2 * n.length + deflated.length).order(ByteOrder.LITTLE_ENDIAN);
    b.putInt(0x04034b50).putShort((short) 45).putShort((short) 0).putShort((short) 8).putShort((short) 0)
        .putShort((short) 0x21).putInt(0).putInt(-1).putInt(-1).putShort((short) n.length).putShort((short) 20);
    b.put(n).putShort((short) 1).putShort((short) 16).putLong(declared).putLong(deflated.length);
    b.put(deflated);
    int central = b.position();
    b.putInt(0x02014b50).putShort((short) 45).putShort((short) 45).putShort((short) 0).putShort((short) 8)
        .putShort((short) 0).putShort((short) 0x21).putInt(0).putInt(-1).putInt(-1).putShort((short) n.length)
        .putShort((short) 28).putShort((short) 0).putShort((short) 0).putShort((short) 0).putInt(0).putInt(-1);
    b.put(n).putShort((short) 1).putShort((short) 24).putLong(declared).putLong(deflated.length).putLong(0);
    int size = b.position() - central;
    b.putInt(0x06054b50).putShort((short) 0).putShort((short) 0).putShort((short) 1).putShort((short) 1)
        .putInt(size).putInt(central).putShort((short) 0);
    byte[] out = new byte[b.position()];
    b.flip().get(out);
    return out;
  }
}
