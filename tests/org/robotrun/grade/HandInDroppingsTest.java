package org.robotrun.grade;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.io.HandIn;
import org.robotrun.io.HandInDroppings;

/**
 * What operating systems and course platforms add to a hand-in (__MACOSX/, ._ files, .DS_Store,
 * Thumbs.db, .git/) is ignored and listed, never failed; anything else not in the manifest still
 * fails the hand-in check.
 */
class HandInDroppingsTest {
  private static final Path TASK = Path.of("scenarios/tasks/pick-and-place.task.json");
  private static final Path REFERENCE = Path.of("tests/resources/grade/reference");
  private static final byte[] APPLE_DOUBLE = {0, 5, 22, 7, 0, 2, 0, 0, 'M', 'a', 'c', ' ', 'O', 'S', ' ', 'X'};

  @TempDir Path dir;

  @Test
  void theRuleNamesOperatingSystemAndPlatformFilesOnly() {
    assertThat(HandInDroppings.isDropping("__MACOSX/programs/._PICKPLACE.LS")).isTrue();
    assertThat(HandInDroppings.isDropping("__MACOSX/")).isTrue();
    assertThat(HandInDroppings.isDropping("programs/._PICKPLACE.LS")).isTrue();
    assertThat(HandInDroppings.isDropping(".DS_Store")).isTrue();
    assertThat(HandInDroppings.isDropping("programs/Thumbs.db")).isTrue();
    assertThat(HandInDroppings.isDropping(".git/objects/ab/cdef")).isTrue();
    assertThat(HandInDroppings.isDropping(".robotrun/robotrun.jar")).isTrue();
    assertThat(HandInDroppings.isDropping("programs/PICKPLACE.LS")).isFalse();
    assertThat(HandInDroppings.isDropping("cell.json")).isFalse();
    assertThat(HandInDroppings.isDropping("scenarios/x.json")).isFalse();
    assertThat(HandInDroppings.isDropping("notes.txt")).isFalse();
  }

  private Map<String, byte[]> reference() throws Exception {
    Map<String, byte[]> files = new LinkedHashMap<>();
    files.put("cell.json", Files.readAllBytes(REFERENCE.resolve("cell.json")));
    files.put("programs/PICKPLACE.LS", Files.readAllBytes(REFERENCE.resolve("programs/PICKPLACE.LS")));
    return files;
  }

  /** The hand-in as a Mac's "Compress" makes it again: AppleDouble files and __MACOSX/ added. */
  private Path rezippedOnAMac(Map<String, byte[]> extra) throws Exception {
    Path clean = HandIns.zip(reference(), "Ada Lovelace", dir.resolve("clean.zip"));
    Map<String, byte[]> entries = new LinkedHashMap<>();
    try (var z = new java.util.zip.ZipInputStream(Files.newInputStream(clean))) {
      for (var e = z.getNextEntry(); e != null; e = z.getNextEntry()) {
        entries.put(e.getName(), z.readAllBytes());
      }
    }
    entries.put("__MACOSX/", new byte[0]);
    entries.put("__MACOSX/._cell.json", APPLE_DOUBLE);
    entries.put("__MACOSX/programs/._PICKPLACE.LS", APPLE_DOUBLE);
    entries.put("programs/._PICKPLACE.LS", APPLE_DOUBLE);
    entries.put(".DS_Store", "Bud1".getBytes(StandardCharsets.US_ASCII));
    entries.putAll(extra);
    Path zip = dir.resolve("mac.zip");
    Files.write(zip, HandIns.rawZip(entries));
    return zip;
  }

  @Test
  void aHandInZippedAgainOnAMacIsStillValidAndSaysWhatWasIgnored() throws Exception {
    TaskLoad.Loaded t = (TaskLoad.Loaded) TaskReader.read(TASK);
    GradeResult r = Grading.gradeOne(new Grader(t.task(), t.scenario()), new SubmissionLoader(),
        rezippedOnAMac(Map.of()), true);
    CheckResult handIn = HandIns.check(r, "Hand-in");
    assertThat(handIn.passed()).as(handIn.feedback()).isTrue();
    assertThat(handIn.feedback()).contains("note: ignored (operating system or platform files, not part of the hand-in): "
        + "__MACOSX/._cell.json, __MACOSX/programs/._PICKPLACE.LS, programs/._PICKPLACE.LS, .DS_Store");
    assertThat(HandIns.check(r, "Programs read").passed()).as("the AppleDouble file is not read as a program").isTrue();
    assertThat(r.score()).isEqualTo(105);

    // The window's own hand-in reader takes it too.
    HandIn.Manifest m = HandIn.unpack(dir.resolve("mac.zip"), dir.resolve("unpacked"));
    assertThat(m.student()).isEqualTo("Ada Lovelace");
  }

  @Test
  void aFileThatIsNoDroppingAndNotInTheManifestStillFails() throws Exception {
    TaskLoad.Loaded t = (TaskLoad.Loaded) TaskReader.read(TASK);
    Map<String, byte[]> extra = Map.of("programs/EXTRA.LS", "/PROG EXTRA\n/MN\n/END\n".getBytes(StandardCharsets.US_ASCII));
    GradeResult r = Grading.gradeOne(new Grader(t.task(), t.scenario()), new SubmissionLoader(), rezippedOnAMac(extra),
        true);
    CheckResult handIn = HandIns.check(r, "Hand-in");
    assertThat(handIn.passed()).isFalse();
    assertThat(handIn.feedback()).contains("\"programs/EXTRA.LS\" is in the hand-in but not in manifest.json");
  }
}
