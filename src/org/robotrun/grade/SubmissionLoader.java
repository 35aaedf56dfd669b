package org.robotrun.grade;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import org.robotrun.io.HandIn;
import org.robotrun.io.HandInException;
import org.robotrun.io.HandInFiles;
import org.robotrun.io.Workspace;

/**
 * Finds a submission's programs and cell: a hand-in {@code .zip} (root {@code manifest.json},
 * {@code cell.json}, {@code programs/*.LS}, {@code programs/ROBOT/*.LS}), the same unpacked in a
 * folder, a workspace folder ({@code cell.json} + {@code programs/}), a folder laid out as one
 * without {@code cell.json}, or a folder of {@code .LS} files.
 *
 * <p>Every kind is read by the one hand-in reader, {@link HandInFiles}, under its one table of
 * limits (names, sizes counted as the bytes come, no links, no special files), then the files
 * grading needs are copied into a fresh private temporary folder: nothing is read from the
 * student's files after that, and nothing outside them ever.
 */
public final class SubmissionLoader {
  /** The limits of one submission: the one table of hand-in limits ({@link HandInFiles.Limits}). */
  public static final HandInFiles.Limits DEFAULT_LIMITS = HandInFiles.Limits.DEFAULT;

  private final HandInFiles.Limits limits;

  public SubmissionLoader(HandInFiles.Limits limits) {
    this.limits = limits;
  }

  public SubmissionLoader() {
    this(DEFAULT_LIMITS);
  }

  public HandInFiles.Limits limits() {
    return limits;
  }

  /** Looks at {@code path} and loads it; never throws: problems come back in the submission. */
  public Submission load(Path path) {
    String name = String.valueOf(path.getFileName());
    try {
      if (Files.isDirectory(path)) {
        return folder(path, name);
      }
      if (Files.isRegularFile(path) && name.toLowerCase(Locale.ROOT).endsWith(".zip")) {
        return zip(path, name);
      }
      return Submission.failed(name, Submission.Kind.PROGRAMS, Files.exists(path)
          ? "not a hand-in .zip, a workspace folder or a folder of .LS files"
          : "no such file or folder", Optional.empty());
    } catch (IOException | RuntimeException e) {
      return Submission.failed(name, Submission.Kind.PROGRAMS, "cannot read: " + describe(e), Optional.empty());
    }
  }

  /**
   * A folder: an unpacked hand-in (Gradescope unpacks an uploaded .zip), a workspace, a folder
   * laid out as one ({@code programs/}, no {@code cell.json}) or a plain folder of {@code .LS}
   * files. Read as a zip is (the same reader and limits; links and special files refused) and
   * copied, so grading never looks at the student's folder again.
   */
  private Submission folder(Path dir, String name) throws IOException {
    boolean cell = Files.exists(dir.resolve(Workspace.CELL), LinkOption.NOFOLLOW_LINKS);
    boolean manifest = Files.exists(dir.resolve(HandIn.MANIFEST), LinkOption.NOFOLLOW_LINKS);
    boolean programs = Files.exists(dir.resolve(Workspace.PROGRAMS), LinkOption.NOFOLLOW_LINKS);
    HandInFiles.Contents c;
    List<String> problems = new ArrayList<>();
    String student = "";
    Submission.Kind kind = cell || programs ? Submission.Kind.WORKSPACE : Submission.Kind.PROGRAMS;
    try {
      if (cell || manifest || programs) {
        List<String> others = new ArrayList<>();
        c = HandInFiles.readFolder(dir, limits, others);
        if (manifest) {
          HandInFiles.Verified v = HandInFiles.verify(c);
          student = v.student();
          problems.addAll(v.problems());
          others.forEach(o -> problems.add("\"" + HandInFiles.printable(o) + "\" is not part of a hand-in"));
          if (!cell) {
            kind = Submission.Kind.PROGRAMS;
          }
        } else {
          problems.add(cell ? "a workspace folder, not a hand-in .zip" : "a folder of programs, not a hand-in .zip");
        }
      } else {
        c = HandInFiles.readProgramFolder(dir, limits);
        problems.add("a folder of programs, not a hand-in .zip");
      }
    } catch (HandInException e) {
      return Submission.failed(name, kind, e.getMessage(), Optional.empty());
    }
    return copied(name, kind, c, student, problems);
  }

  private Submission zip(Path file, String name) throws IOException {
    HandInFiles.Contents c;
    try {
      c = HandInFiles.readZip(file, limits);
    } catch (HandInException e) {
      return Submission.failed(name, Submission.Kind.ZIP, e.getMessage(), Optional.empty());
    }
    HandInFiles.Verified v = HandInFiles.verify(c);
    return copied(name, Submission.Kind.ZIP, c, v.student(), v.problems());
  }

  /**
   * Writes the files grading reads ({@code cell.json} and the programs) into a fresh private
   * temporary folder, which {@link Submission#close} removes; when writing fails it is removed
   * here. Only called once the whole submission has passed: a hostile one costs no disk writes.
   */
  private static Submission copied(String name, Submission.Kind kind, HandInFiles.Contents c, String student,
      List<String> problems) throws IOException {
    Map<String, byte[]> used = new TreeMap<>();
    c.files().forEach((entry, bytes) -> {
      if (entry.equals(Workspace.CELL) || entry.startsWith(Workspace.PROGRAMS + "/")) {
        used.put(entry, bytes);
      }
    });
    Path temp = Files.createTempDirectory("robotrun-grade-",
        PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rwx------")));
    try {
      HandInFiles.writeTo(used, temp);
    } catch (IOException | RuntimeException e) {
      Submission.deleteTree(temp);
      return Submission.failed(name, kind, "cannot copy the submission to a temporary folder: " + describe(e),
          Optional.empty());
    }
    Optional<Path> cell = used.containsKey(Workspace.CELL) ? Optional.of(temp.resolve(Workspace.CELL)) : Optional.empty();
    return new Submission(name, kind, temp.resolve(Workspace.PROGRAMS), cell, student, problems, Optional.empty(),
        Optional.of(temp));
  }

  static boolean isLs(String name) {
    return name.length() > 3 && name.regionMatches(true, name.length() - 3, ".ls", 0, 3);
  }

  static String describe(Throwable e) {
    return e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
  }
}
