package org.robotrun.io;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;

/**
 * A file that could not be read at all: missing, not a regular file, no permission, above its
 * size limit. {@link #getMessage()} is the reason alone, in words fit to show a user ("no such
 * file", "a folder, not a regular file"); {@link #file()} is the file.
 */
public final class UnreadableFileException extends IOException {
  private final Path file;

  public UnreadableFileException(Path file, String reason) {
    super(reason);
    this.file = file;
  }

  /** The reason for a failed file operation, in words (not the JDK's "path: reason" form). */
  static UnreadableFileException of(Path file, IOException e) {
    String reason = switch (e) {
      case NoSuchFileException x -> BoundedFiles.NO_SUCH_FILE;
      case AccessDeniedException x -> "permission denied";
      default -> {
        String m = e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
        // The JDK often says "<path>: <reason>"; the caller names the file already.
        String prefix = file + ": ";
        yield m.startsWith(prefix) ? m.substring(prefix.length()) : m;
      }
    };
    return new UnreadableFileException(file, reason);
  }

  public Path file() {
    return file;
  }
}
