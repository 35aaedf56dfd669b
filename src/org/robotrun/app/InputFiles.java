package org.robotrun.app;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.robotrun.io.BoundedFiles;
import org.robotrun.io.FileFormatException;
import org.robotrun.io.UnreadableFileException;

/** Reading a small text input named by an option, with every problem as a {@link UserError}. */
final class InputFiles {
  private InputFiles() {}

  /**
   * The lines of a UTF-8 text file within {@code maxBytes}; a missing file, a FIFO, a device, a
   * folder, a file too large or malformed UTF-8 (with its line) is bad input.
   */
  static List<String> lines(String option, Path file, long maxBytes, String what) {
    try {
      String text = BoundedFiles.readUtf8(file, maxBytes, what);
      return text.lines().toList();
    } catch (UnreadableFileException e) {
      if (e.getMessage().equals(BoundedFiles.NO_SUCH_FILE)) {
        throw new UserError(Files.isSymbolicLink(file) ? option + ": " + file + " is " + BoundedFiles.missing(file)
            : option + ": no such file " + file);
      }
      throw new UserError(option + ": cannot read " + file + ": " + e.getMessage());
    } catch (FileFormatException e) {
      throw new UserError(option + ": " + e.getMessage());
    }
  }
}
