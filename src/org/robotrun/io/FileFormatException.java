package org.robotrun.io;

/**
 * Bad input in a file: names the file, the line (0 when unknown) and what was expected.
 * Its message is fit to show a user as is.
 */
public class FileFormatException extends RuntimeException {
  private final String file;
  private final int line;
  private final String reason;

  public FileFormatException(String file, int line, String message) {
    super(line > 0 ? file + ":" + line + ": " + message : file + ": " + message);
    this.file = file;
    this.line = line;
    this.reason = message;
  }

  /** What was wrong, without the file and line. */
  public String reason() {
    return reason;
  }

  public String file() {
    return file;
  }

  public int line() {
    return line;
  }
}
