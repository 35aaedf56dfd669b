package org.robotrun.grade;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;
import java.util.stream.Stream;

/**
 * A submission as found on disk, ready to grade: its programs and, for a workspace or a hand-in,
 * its cell.json. Its files are copied (within {@link SubmissionLoader}'s limits) into a
 * private temporary folder that {@link #close} removes.
 *
 * @param name what reports call it (the zip's or folder's file name)
 * @param kind what was given
 * @param programsDir the folder whose *.LS files are the programs (null when {@code fatal})
 * @param cell the cell.json, if there is one
 * @param student the student's name from the manifest ("" when none)
 * @param handInProblems why this is not a valid hand-in (empty: it is)
 * @param fatal why the submission cannot be graded at all (a malformed zip, too many files)
 * @param tempDir the folder to remove on close, if the zip was unpacked
 */
public record Submission(String name, Kind kind, Path programsDir, Optional<Path> cell, String student,
    List<String> handInProblems, Optional<String> fatal, Optional<Path> tempDir) implements AutoCloseable {

  public Submission {
    handInProblems = List.copyOf(handInProblems);
  }

  /** What a submission was given as. */
  public enum Kind {
    /** A hand-in .zip (CONTRACTS item 2). */
    ZIP,
    /** A workspace folder: cell.json and programs/*.LS. */
    WORKSPACE,
    /** A folder of .LS files, run on the task's scenario. */
    PROGRAMS
  }

  /** A submission that cannot be graded, with the reason. */
  static Submission failed(String name, Kind kind, String reason, Optional<Path> tempDir) {
    return new Submission(name, kind, null, Optional.empty(), "", List.of(reason), Optional.of(reason), tempDir);
  }

  /** Removes the copy of the submission's files, if any. */
  @Override
  public void close() {
    tempDir.ifPresent(Submission::deleteTree);
  }

  /** Removes a folder and all in it, without following links (best effort: grading goes on). */
  static void deleteTree(Path dir) {
    try (Stream<Path> s = Files.walk(dir)) {
      for (Path p : s.sorted(Comparator.reverseOrder()).toList()) {
        try {
          Files.deleteIfExists(p);
        } catch (IOException e) {
          // the rest is still removed
        }
      }
    } catch (IOException e) {
      // the OS cleans its temporary folder
    }
  }
}
