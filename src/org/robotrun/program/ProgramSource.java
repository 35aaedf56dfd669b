package org.robotrun.program;

import java.nio.charset.Charset;
import java.util.List;

/**
 * The text a program was read from, kept so that writing it back changes nothing the user did
 * not change: an unedited program is written back byte for byte, and an edited one keeps the
 * layout of every line, /ATTR, /APPL and /POS it did not touch (TP-LANGUAGE.md, "Program
 * file").
 *
 * @param bytes the file as read
 * @param charset how its bytes were decoded (UTF-8, or ISO-8859-1 for Latin-1 listings)
 * @param lineEnd the line separator of the file ({@code "\r\n"} or {@code "\n"})
 * @param asRead the program as read (no source), to tell what was edited since
 * @param header the file's lines up to the first /MN statement (/PROG, /ATTR, /APPL, /MN), each with its line end
 * @param appl the /APPL section's lines, with their line ends (empty when there is none)
 * @param statements for each /MN line of {@code asRead}, its file lines (a continuation line and
 *     blank lines after it included), each with its line end
 * @param tail the lines from /POS (or /END) to the end of the file, with their line ends
 */
public record ProgramSource(byte[] bytes, Charset charset, String lineEnd, Program asRead, List<String> header,
    List<String> appl, List<List<String>> statements, List<String> tail) {

  public ProgramSource {
    header = List.copyOf(header);
    appl = List.copyOf(appl);
    statements = statements.stream().map(List::copyOf).toList();
    tail = List.copyOf(tail);
    if (statements.size() != asRead.lineCount()) {
      throw new IllegalArgumentException(statements.size() + " statement texts for " + asRead.lineCount() + " lines");
    }
  }

  /** The file's bytes (a copy). */
  public byte[] bytes() {
    return bytes.clone();
  }
}
