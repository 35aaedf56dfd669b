package org.robotrun.io;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.Locale;

/**
 * The one way RobotRun reads a whole input file, so that no file can exhaust memory or hang a
 * command: only regular files are opened (a FIFO, a device or a folder is refused by name,
 * before it is opened, so a pipe with no writer cannot block), and the bytes are counted as they
 * come from the stream, not taken from the file's size, which is 0 for devices and wrong for
 * files that grow while being read.
 *
 * <p>A file that cannot be read is an {@link UnreadableFileException} whose message says why in
 * words fit to show a user ("no such file", "a named pipe (FIFO), not a regular file"); bad
 * content (malformed UTF-8) is a {@link FileFormatException} naming the file and line.
 */
public final class BoundedFiles {
  private BoundedFiles() {}

  /** The reason given for a missing file. */
  public static final String NO_SUCH_FILE = "no such file";

  /**
   * Why {@code file} cannot be found, in words: {@link #NO_SUCH_FILE}, or, for a symbolic link
   * whose target is missing or that loops back on itself, that it is such a link.
   */
  public static String missing(Path file) {
    if (Files.isSymbolicLink(file)) {
      return "a symbolic link that leads nowhere (its target is missing, or the links form a loop)";
    }
    return NO_SUCH_FILE;
  }

  /**
   * Reads all of {@code file}, refusing it when it holds more than {@code maxBytes}.
   *
   * @param what what the file should be, for the limit message ("scenario files", "STL meshes")
   * @throws UnreadableFileException missing, not a regular file, unreadable, or above the limit
   */
  public static byte[] read(Path file, long maxBytes, String what) throws UnreadableFileException {
    long declared = requireRegularFile(file);
    if (declared > maxBytes) {
      // A regular file's size is known before reading: refuse a 3 GiB file without touching it.
      throw new UnreadableFileException(file, String.format(Locale.ROOT, "file is %.1f MiB; %s are limited to %s",
          declared / 1048576.0, what, sizeText(maxBytes)));
    }
    try (InputStream in = Files.newInputStream(file)) {
      int cap = (int) Math.min(maxBytes + 1, Integer.MAX_VALUE - 16);
      byte[] bytes = in.readNBytes(cap);
      if (bytes.length > maxBytes) {
        // grew while being read (or its size lied): the count from the stream decides
        throw new UnreadableFileException(file, "more than " + sizeText(maxBytes) + "; " + what + " are limited to "
            + sizeText(maxBytes));
      }
      return bytes;
    } catch (UnreadableFileException e) {
      throw e;
    } catch (IOException e) {
      throw UnreadableFileException.of(file, e);
    }
  }

  /**
   * Reads {@code file} as UTF-8 text (a leading byte-order mark is dropped), within
   * {@code maxBytes}. Malformed UTF-8 is reported with the line it is on.
   */
  public static String readUtf8(Path file, long maxBytes, String what) throws UnreadableFileException {
    byte[] bytes = read(file, maxBytes, what);
    String text = decodeUtf8(file.toString(), bytes);
    return text.startsWith("\uFEFF") ? text.substring(1) : text;
  }

  /** Decodes strict UTF-8; a bad byte is an error naming its line (1-based). */
  public static String decodeUtf8(String name, byte[] bytes) {
    try {
      return StandardCharsets.UTF_8.newDecoder()
          .onMalformedInput(CodingErrorAction.REPORT)
          .onUnmappableCharacter(CodingErrorAction.REPORT)
          .decode(ByteBuffer.wrap(bytes)).toString();
    } catch (CharacterCodingException e) {
      int bad = firstBadUtf8(bytes);
      int line = 1;
      for (int i = 0; i < bad; i++) {
        if (bytes[i] == '\n') line++;
      }
      throw new FileFormatException(name, line, "not UTF-8 text (byte " + String.format(Locale.ROOT, "0x%02X",
          bytes[bad] & 0xFF) + " at offset " + bad + "); save the file as UTF-8");
    }
  }

  /**
   * Refuses anything but an existing regular file (symbolic links are followed), naming what it
   * is instead. Never opens the file, so a FIFO does not block. Returns the size the file system
   * gives, which a reader may use to refuse early but must not trust as the count of bytes.
   */
  public static long requireRegularFile(Path file) throws UnreadableFileException {
    BasicFileAttributes a;
    try {
      a = Files.readAttributes(file, BasicFileAttributes.class);
    } catch (IOException e) {
      throw UnreadableFileException.of(file, e);
    }
    if (!a.isRegularFile()) {
      throw new UnreadableFileException(file, kind(file, a) + ", not a regular file");
    }
    return a.size();
  }

  /** "a folder", "a named pipe (FIFO)", "a character device", … for a path that is not a regular file. */
  static String kind(Path file, BasicFileAttributes a) {
    if (a.isDirectory()) return "a folder";
    try {
      // The unix view is there on Linux and macOS; the file type sits in the high bits of st_mode.
      int mode = (Integer) Files.getAttribute(file, "unix:mode");
      return switch (mode & 0170000) {
        case 0010000 -> "a named pipe (FIFO)";
        case 0020000 -> "a character device";
        case 0060000 -> "a block device";
        case 0140000 -> "a socket";
        default -> "a special file";
      };
    } catch (IOException | UnsupportedOperationException | IllegalArgumentException | ClassCastException e) {
      return "a special file";
    }
  }

  static String sizeText(long bytes) {
    return bytes % (1L << 20) == 0 ? (bytes >> 20) + " MiB" : bytes + " bytes";
  }

  private static int firstBadUtf8(byte[] bytes) {
    var dec = StandardCharsets.UTF_8.newDecoder()
        .onMalformedInput(CodingErrorAction.REPORT).onUnmappableCharacter(CodingErrorAction.REPORT);
    ByteBuffer in = ByteBuffer.wrap(bytes);
    var out = java.nio.CharBuffer.allocate(Math.max(16, bytes.length));
    var r = dec.decode(in, out, true);
    return r.isError() ? Math.min(in.position(), bytes.length - 1) : bytes.length - 1;
  }
}
