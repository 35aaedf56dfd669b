package org.robotrun.io;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.BufferedInputStream;
import java.io.ByteArrayOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import java.util.regex.Pattern;
import java.util.zip.ZipEntry;
import java.util.zip.ZipException;
import java.util.zip.ZipInputStream;

/**
 * The one reader of hand-ins, for {@code run --workspace}, the window and {@code grade} alike:
 * a hand-in {@code .zip} or the same files unpacked in a folder (as Gradescope gives them), read
 * into memory under one table of {@link Limits} (docs/workspace.md, "Hand-in"), with one rule
 * for names. Nothing is written and nothing outside the hand-in is ever opened: in a folder a
 * symbolic link, a FIFO, a device or a socket is refused by name, never followed or opened.
 *
 * <p>A zip is streamed entry by entry and its declared sizes are ignored: the entries, each
 * entry's bytes and the total are counted as they are inflated, so a zip bomb costs at most
 * {@link Limits#totalBytes} whatever its headers claim. Names must be relative, without
 * {@code ..}, drive letters, backslashes or control characters, valid UTF-8, unique (the
 * manifest too), and one of: {@code manifest.json}, {@code cell.json}, {@code programs/NAME.LS},
 * {@code programs/ROBOT/NAME.LS}, {@code scenarios/NAME.json}. What {@link HandIn#write} writes
 * always passes.
 */
public final class HandInFiles {
  private static final ObjectMapper JSON = new ObjectMapper();

  /**
   * The one table of hand-in limits.
   *
   * @param entries most entries of a zip (or files of a folder), the manifest included
   * @param entryBytes most uncompressed bytes of one file
   * @param totalBytes most uncompressed bytes of all files together
   */
  public record Limits(int entries, long entryBytes, long totalBytes) {
    /** 2000 entries, 16 MiB a file (the largest .LS or scenario file RobotRun reads), 64 MiB in all. */
    public static final Limits DEFAULT = new Limits(2000, 16L << 20, 64L << 20);
  }

  /** programs/NAME.LS, or programs/ROBOT/NAME.LS for a later robot of the cell (no "..", no deeper folders). */
  static final Pattern PROGRAM_ENTRY = Pattern.compile(
      "programs/(?:[A-Za-z0-9_][A-Za-z0-9_.\\-]{0,63}/)?[A-Za-z0-9_][A-Za-z0-9_.\\-]{0,63}\\.(?i:ls)");
  /** The folder of a later robot's programs. */
  private static final Pattern ROBOT_FOLDER = Pattern.compile("programs/[A-Za-z0-9_][A-Za-z0-9_.\\-]{0,63}/");
  /** The cell editor's other named scenarios: {@code scenarios/NAME.json}. */
  static final Pattern SCENARIO_ENTRY = Pattern.compile(Workspace.SCENARIOS + "/" + Workspace.SCENARIO_FILE.pattern());

  private HandInFiles() {}

  /**
   * What a hand-in holds.
   *
   * @param manifest the bytes of {@code manifest.json}, null when there is none
   * @param files every other file, by its name in the hand-in, sorted
   */
  public record Contents(byte[] manifest, Map<String, byte[]> files) {}

  /** What {@link #verify} found: the student's name and what makes this not a valid hand-in. */
  public record Verified(String student, List<String> problems) {}

  /** Whether {@code name} is a file a hand-in may hold. */
  public static boolean isHandInName(String name) {
    return name.equals(HandIn.MANIFEST) || name.equals(Workspace.CELL) || PROGRAM_ENTRY.matcher(name).matches()
        || SCENARIO_ENTRY.matcher(name).matches();
  }

  /**
   * Reads a hand-in zip. The message of the exception says what is wrong and names the entry,
   * not the zip (the caller names it).
   */
  public static Contents readZip(Path zip, Limits limits) throws HandInException {
    long size;
    try {
      size = BoundedFiles.requireRegularFile(zip);  // a FIFO or a device is named, never opened
    } catch (UnreadableFileException e) {
      throw new HandInException(e.getMessage());
    }
    if (size > limits.totalBytes()) {
      throw new HandInException("the file is " + size + " bytes; a hand-in is at most " + sizeText(limits.totalBytes()));
    }
    TreeMap<String, byte[]> files = new TreeMap<>();
    byte[] manifest = null;
    int entries = 0;
    long total = 0;
    try (InputStream in = Files.newInputStream(zip);
        ZipInputStream z = new ZipInputStream(new BufferedInputStream(in), StandardCharsets.UTF_8)) {
      while (true) {
        ZipEntry e;
        try {
          e = z.getNextEntry();
        } catch (IllegalArgumentException bad) {
          throw notUtf8(entries);
        }
        if (e == null) {
          break;
        }
        if (++entries > limits.entries()) {
          throw new HandInException("the zip has more than " + limits.entries() + " entries");
        }
        String name = e.getName();
        Optional<String> bad = badName(name);
        if (bad.isPresent()) {
          throw new HandInException("the zip entry \"" + printable(name) + "\" " + bad.get());
        }
        if (e.isDirectory()) {
          if (name.equals(Workspace.PROGRAMS + "/") || ROBOT_FOLDER.matcher(name).matches()
              || name.equals(Workspace.SCENARIOS + "/")) {
            continue;
          }
          throw unexpected(name);
        }
        if (!isHandInName(name)) {
          throw unexpected(name);
        }
        if (files.containsKey(name) || (name.equals(HandIn.MANIFEST) && manifest != null)) {
          throw new HandInException("the zip holds \"" + name + "\" twice");
        }
        byte[] bytes = readBounded(z, name, limits, limits.totalBytes() - total);
        total += bytes.length;
        if (name.equals(HandIn.MANIFEST)) {
          manifest = bytes;
        } else {
          files.put(name, bytes);
        }
      }
    } catch (ZipException | EOFException e) {
      if (String.valueOf(e.getMessage()).contains("bad entry name")) {
        throw notUtf8(entries);
      }
      throw new HandInException("not a readable zip file (" + describe(e) + ")");
    } catch (NoSuchFileException e) {
      throw new HandInException(BoundedFiles.NO_SUCH_FILE);
    } catch (IOException e) {
      throw new HandInException("cannot read (" + describe(e) + ")");
    }
    if (entries == 0) {
      throw new HandInException("not a zip file, or an empty one");
    }
    requireNoFileInsideAFile(files.keySet());
    return new Contents(manifest, files);
  }

  /**
   * Reads a hand-in (or a workspace) unpacked in {@code dir}: {@code manifest.json},
   * {@code cell.json}, {@code programs/*.LS}, {@code programs/ROBOT/*.LS} and
   * {@code scenarios/*.json}, under the same limits as a zip. Links and special files are
   * refused, never followed; other files are left alone and listed in {@code others}.
   */
  public static Contents readFolder(Path dir, Limits limits, List<String> others) throws HandInException {
    TreeMap<String, byte[]> files = new TreeMap<>();
    byte[] manifest = null;
    long[] total = {0};
    int[] count = {0};
    for (String top : List.of(HandIn.MANIFEST, Workspace.CELL)) {
      Path p = dir.resolve(top);
      if (kindOf(p, top).isPresent()) {
        byte[] bytes = readOwnFile(p, top, limits, total, count);
        if (top.equals(HandIn.MANIFEST)) {
          manifest = bytes;
        } else {
          files.put(top, bytes);
        }
      }
    }
    Path programs = dir.resolve(Workspace.PROGRAMS);
    if (isOwnFolder(programs, Workspace.PROGRAMS)) {
      for (Path p : list(programs, Workspace.PROGRAMS, limits)) {
        String name = Workspace.PROGRAMS + "/" + p.getFileName();
        if (isOwnFolder(p, name)) {
          for (Path q : list(p, name, limits)) {
            String inner = name + "/" + q.getFileName();
            take(q, inner, limits, total, count, files, others);
          }
        } else {
          take(p, name, limits, total, count, files, others);
        }
      }
    }
    Path scenarios = dir.resolve(Workspace.SCENARIOS);
    if (isOwnFolder(scenarios, Workspace.SCENARIOS)) {
      for (Path p : list(scenarios, Workspace.SCENARIOS, limits)) {
        take(p, Workspace.SCENARIOS + "/" + p.getFileName(), limits, total, count, files, others);
      }
    }
    return new Contents(manifest, files);
  }

  /**
   * Reads a plain folder of {@code .LS} files as the first robot's programs
   * ({@code programs/NAME.LS}), and its subfolders' {@code .LS} files as a later robot's
   * ({@code programs/ROBOT/NAME.LS}); links and special files among them are refused, other
   * files are not read.
   */
  public static Contents readProgramFolder(Path dir, Limits limits) throws HandInException {
    TreeMap<String, byte[]> files = new TreeMap<>();
    long[] total = {0};
    int[] count = {0};
    for (Path p : list(dir, ".", limits)) {
      String file = p.getFileName().toString();
      if (isOwnFolder(p, file)) {
        for (Path q : list(p, file, limits)) {
          String inner = file + "/" + q.getFileName();
          if (isLs(inner)) {
            readProgram(q, inner, limits, total, count, files);
          }
        }
      } else if (isLs(file)) {
        readProgram(p, file, limits, total, count, files);
      }
    }
    return new Contents(null, files);
  }

  private static boolean isLs(String file) {
    return file.length() > 3 && file.regionMatches(true, file.length() - 3, ".ls", 0, 3);
  }

  private static void readProgram(Path p, String shown, Limits limits, long[] total, int[] count,
      Map<String, byte[]> files) throws HandInException {
    String name = Workspace.PROGRAMS + "/" + shown;
    if (!PROGRAM_ENTRY.matcher(name).matches()) {
      throw new HandInException("\"" + printable(shown) + "\" is not a program file name (letters, digits, '_', '.' and"
          + " '-', at most 64 characters before .LS)");
    }
    files.put(name, readOwnFile(p, shown, limits, total, count));
  }

  private static void take(Path p, String name, Limits limits, long[] total, int[] count, Map<String, byte[]> files,
      List<String> others) throws HandInException {
    if (isHandInName(name)) {
      files.put(name, readOwnFile(p, name, limits, total, count));
    } else {
      kindOf(p, name);  // a link or special file is refused even where it would not be read
      others.add(name);
    }
  }

  /** The files of a folder, refused past the entry limit (counted without reading them). */
  private static List<Path> list(Path dir, String name, Limits limits) throws HandInException {
    List<Path> out = new ArrayList<>();
    try (DirectoryStream<Path> s = Files.newDirectoryStream(dir)) {
      for (Iterator<Path> it = s.iterator(); it.hasNext(); ) {
        out.add(it.next());
        if (out.size() > limits.entries()) {
          throw new HandInException((name.equals(".") ? "the folder" : "\"" + name + "\"") + " holds more than "
              + limits.entries() + " files; a submission may hold at most " + limits.entries());
        }
      }
    } catch (IOException e) {
      throw new HandInException("cannot list \"" + name + "\" (" + describe(e) + ")");
    }
    out.sort(null);
    return out;
  }

  /** Whether {@code p} is a real folder of the submission (a link to a folder is refused). */
  private static boolean isOwnFolder(Path p, String name) throws HandInException {
    Optional<BasicFileAttributes> a = kindOf(p, name);
    return a.isPresent() && a.get().isDirectory();
  }

  /**
   * The attributes of {@code p} without following a link; empty when it does not exist.
   *
   * @throws HandInException when it is a link or a special file
   */
  private static Optional<BasicFileAttributes> kindOf(Path p, String name) throws HandInException {
    BasicFileAttributes a;
    try {
      a = Files.readAttributes(p, BasicFileAttributes.class, LinkOption.NOFOLLOW_LINKS);
    } catch (NoSuchFileException e) {
      return Optional.empty();
    } catch (IOException e) {
      throw new HandInException("cannot read \"" + printable(name) + "\" (" + describe(e) + ")");
    }
    if (a.isSymbolicLink()) {
      throw new HandInException("\"" + printable(name) + "\" is a symbolic link; a submission is read only from its own"
          + " files, never through a link");
    }
    if (!a.isRegularFile() && !a.isDirectory()) {
      throw new HandInException("\"" + printable(name) + "\" is " + BoundedFiles.kind(p, a) + ", not a regular file");
    }
    return Optional.of(a);
  }

  private static byte[] readOwnFile(Path p, String name, Limits limits, long[] total, int[] count)
      throws HandInException {
    Optional<BasicFileAttributes> a = kindOf(p, name);
    if (a.isEmpty()) {
      throw new HandInException("\"" + printable(name) + "\" disappeared while it was read");
    }
    if (a.get().isDirectory()) {
      throw new HandInException("\"" + printable(name) + "\" is a folder, not a file");
    }
    if (++count[0] > limits.entries()) {
      throw new HandInException("the submission holds more than " + limits.entries() + " files");
    }
    // NOFOLLOW_LINKS: a link swapped in after the check is refused by the system, not followed.
    try (InputStream in = Files.newInputStream(p, LinkOption.NOFOLLOW_LINKS)) {
      byte[] bytes = readBounded(in, name, limits, limits.totalBytes() - total[0]);
      total[0] += bytes.length;
      return bytes;
    } catch (IOException e) {
      throw new HandInException("cannot read \"" + printable(name) + "\" (" + describe(e) + ")");
    }
  }

  /** Reads one file, at most the entry limit and at most {@code budget}, counting the bytes as they come. */
  private static byte[] readBounded(InputStream in, String name, Limits limits, long budget)
      throws IOException, HandInException {
    long cap = Math.min(limits.entryBytes(), budget) + 1;
    ByteArrayOutputStream out = new ByteArrayOutputStream();
    byte[] buf = new byte[8192];
    long n = 0;
    int r;
    while (n < cap && (r = in.read(buf, 0, (int) Math.min(buf.length, cap - n))) > 0) {
      out.write(buf, 0, r);
      n += r;
    }
    if (n > limits.entryBytes()) {
      throw new HandInException("\"" + printable(name) + "\" unpacks to more than " + sizeText(limits.entryBytes()));
    }
    if (n > budget) {
      throw new HandInException("the hand-in unpacks to more than " + sizeText(limits.totalBytes()) + " (at \""
          + printable(name) + "\")");
    }
    return out.toByteArray();
  }

  /** {@code programs/A.LS} and {@code programs/A.LS/B.LS} cannot both be unpacked. */
  private static void requireNoFileInsideAFile(java.util.Set<String> names) throws HandInException {
    for (String n : names) {
      int slash = n.lastIndexOf('/');
      while (slash > 0) {
        String parent = n.substring(0, slash);
        if (names.contains(parent)) {
          throw new HandInException("the zip holds \"" + parent + "\" both as a file and as the folder of \"" + n + "\"");
        }
        slash = parent.lastIndexOf('/');
      }
    }
  }

  /**
   * Checks the manifest against the files: format 1, a student, every file listed with its
   * SHA-256, nothing missing or extra, and a {@code cell.json}. Problems in the order found;
   * none means a valid hand-in.
   */
  public static Verified verify(Contents c) {
    List<String> problems = new ArrayList<>();
    String student = "";
    if (c.manifest() == null) {
      problems.add("the hand-in has no manifest.json at its root (was it made with RobotRun's Hand in?)");
    } else {
      student = checkManifest(c, problems);
    }
    if (!c.files().containsKey(Workspace.CELL)) {
      problems.add("the hand-in has no cell.json at its root");
    }
    return new Verified(student, problems);
  }

  private static String checkManifest(Contents c, List<String> problems) {
    JsonNode m;
    try {
      m = JSON.readTree(c.manifest());
    } catch (IOException e) {
      problems.add("manifest.json is not valid JSON");
      return "";
    }
    if (m == null || !m.isObject()) {
      problems.add("manifest.json is not a JSON object");
      return "";
    }
    JsonNode format = m.path("format");
    if (format.isInt() && format.intValue() > HandIn.FORMAT) {
      problems.add("manifest.json: format " + format.intValue() + " is newer than this RobotRun reads (" + HandIn.FORMAT
          + "); update RobotRun");
    } else if (!format.isInt() || format.intValue() != HandIn.FORMAT) {
      problems.add("manifest.json: expected \"format\": " + HandIn.FORMAT);
    }
    String student = m.path("student").isTextual() ? m.path("student").asText() : "";
    if (student.isBlank()) {
      problems.add("manifest.json names no student");
    }
    JsonNode files = m.path("files");
    if (!files.isObject()) {
      problems.add("manifest.json has no \"files\" object");
      return student;
    }
    for (Map.Entry<String, byte[]> e : c.files().entrySet()) {
      JsonNode h = files.get(e.getKey());
      if (h == null) {
        problems.add("\"" + e.getKey() + "\" is in the hand-in but not in manifest.json");
      } else if (!h.isTextual() || !h.asText().toLowerCase(Locale.ROOT).equals(HandIn.sha256(e.getValue()))) {
        problems.add("\"" + e.getKey() + "\" was changed after the hand-in was made (its SHA-256 does not match"
            + " manifest.json)");
      }
    }
    for (Iterator<String> it = files.fieldNames(); it.hasNext(); ) {
      String f = it.next();
      if (!c.files().containsKey(f)) {
        problems.add("manifest.json lists \"" + printable(f) + "\", which is not in the hand-in");
      }
    }
    return student;
  }

  /**
   * Writes {@code files} into the folder {@code into} (created, must be empty or missing).
   *
   * @throws IOException when the disk refuses; the caller removes {@code into}
   */
  public static void writeTo(Map<String, byte[]> files, Path into) throws IOException {
    Files.createDirectories(into.resolve(Workspace.PROGRAMS));
    for (Map.Entry<String, byte[]> e : files.entrySet()) {
      Path target = into.resolve(e.getKey()).normalize();
      if (!target.startsWith(into)) {
        throw new IOException("\"" + e.getKey() + "\" is outside the folder");  // badName makes this impossible
      }
      Files.createDirectories(target.getParent());
      AtomicFiles.writeLeavingFolderSync(target, e.getValue());
    }
  }

  /** Why a zip entry name is refused, if it is. */
  public static Optional<String> badName(String entry) {
    if (entry.isEmpty() || entry.length() > 255) {
      return Optional.of("has an empty or overlong name");
    }
    if (entry.startsWith("/") || entry.contains("\\") || entry.contains(":") || entry.indexOf('\0') >= 0) {
      return Optional.of("is not a relative path inside the zip (absolute, a drive letter or a backslash)");
    }
    for (String part : entry.split("/")) {
      if (part.equals("..")) {
        return Optional.of("points outside the zip (\"..\")");
      }
    }
    for (int i = 0; i < entry.length(); i++) {
      if (Character.isISOControl(entry.charAt(i))) {
        return Optional.of("has a control character in its name");
      }
    }
    return Optional.empty();
  }

  private static HandInException unexpected(String name) {
    return new HandInException("unexpected entry \"" + printable(name) + "\" (a hand-in holds manifest.json, cell.json,"
        + " programs/NAME.LS, programs/ROBOT/NAME.LS and scenarios/NAME.json only)");
  }

  private static HandInException notUtf8(int entries) {
    return new HandInException("entry " + (entries + 1)
        + " of the zip has a file name that is not UTF-8; make the zip again with RobotRun's Hand in");
  }

  /** At most 100 characters, control characters as '?'. */
  public static String printable(String s) {
    StringBuilder b = new StringBuilder();
    for (int i = 0; i < Math.min(s.length(), 100); i++) {
      char c = s.charAt(i);
      b.append(Character.isISOControl(c) ? '?' : c);
    }
    return s.length() > 100 ? b + "..." : b.toString();
  }

  static String sizeText(long bytes) {
    return BoundedFiles.sizeText(bytes);
  }

  private static String describe(Throwable e) {
    if (e instanceof EOFException) {
      return "it ends in the middle of an entry: cut short?";
    }
    if (e instanceof java.nio.file.AccessDeniedException) {
      return "permission denied";
    }
    return e.getMessage() == null ? "an input error" : e.getMessage();
  }
}
