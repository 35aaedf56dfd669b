package org.robotrun.io;

/**
 * One problem in a scenario file.
 *
 * @param file the file as given
 * @param line 1-based line, 0 when unknown
 * @param path JSON path of the offending value, e.g. {@code objects[3].size.x}; empty for the whole file
 * @param message what was wrong and what was expected
 */
public record ScenarioError(String file, int line, String path, String message) {
  /** {@code file:line: path: message}, fit to show a user. */
  @Override
  public String toString() {
    return file + (line > 0 ? ":" + line : "") + ": " + (path.isEmpty() ? "" : path + ": ") + message;
  }
}
