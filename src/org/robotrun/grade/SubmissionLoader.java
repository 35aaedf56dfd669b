package org.robotrun.grade;

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
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.zip.ZipEntry;
import java.util.zip.ZipException;
import java.util.zip.ZipInputStream;
import org.robotrun.io.AtomicFiles;
import org.robotrun.io.HandIn;
import org.robotrun.io.HandInDroppings;

/**
 * Finds a submission's programs and cell: a hand-in {@code .zip} (CONTRACTS item 2: root
 * {@code manifest.json}, {@code cell.json}, {@code programs/*.LS}), a workspace folder
 * ({@code cell.json} + {@code programs/}) or a folder of {@code .LS} files.
 *
 * <p>A zip is never trusted: it is streamed entry by entry and its declared sizes are ignored;
 * the number of entries, each entry's uncompressed bytes and the total are counted as they are
 * inflated and the read stops at the first limit passed (a zip bomb costs at most
 * {@link Limits#totalBytes} of inflation). Names must be relative, without {@code ..}, drive
 * letters or backslashes (no "zip slip"), valid UTF-8, and unique. Only once the whole zip has
 * passed are the hand-in's own files written out, through {@link AtomicFiles}, into a fresh
 * private temporary folder; every entry is hashed so the manifest can be verified.
 */
public final class SubmissionLoader {
  private static final ObjectMapper JSON = new ObjectMapper();

  /**
   * @param entries most zip entries (or .LS files in a folder)
   * @param entryBytes most uncompressed bytes of one file
   * @param totalBytes most uncompressed bytes of a whole zip
   */
  public record Limits(int entries, long entryBytes, long totalBytes) {
    public static final Limits DEFAULT = new Limits(200, 4L << 20, 32L << 20);
  }

  private final Limits limits;

  public SubmissionLoader(Limits limits) {
    this.limits = limits;
  }

  public SubmissionLoader() {
    this(Limits.DEFAULT);
  }

  public Limits limits() {
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

  private Submission folder(Path dir, String name) throws IOException {
    boolean workspace = Files.isRegularFile(dir.resolve("cell.json"));
    Path programs = workspace ? dir.resolve("programs") : dir;
    Submission.Kind kind = workspace ? Submission.Kind.WORKSPACE : Submission.Kind.PROGRAMS;
    if (!Files.isDirectory(programs)) {
      return Submission.failed(name, kind, "the workspace has no programs/ folder", Optional.empty());
    }
    // Count without collecting, so a folder of 100 000 files is refused after limit + 1 names.
    int count = 0;
    try (DirectoryStream<Path> s = Files.newDirectoryStream(programs)) {
      for (Iterator<Path> it = s.iterator(); it.hasNext(); ) {
        Path p = it.next();
        if (isLs(p.getFileName().toString()) && ++count > limits.entries()) {
          return Submission.failed(name, kind, "more than " + limits.entries() + " .LS files; a submission may hold at most "
              + limits.entries(), Optional.empty());
        }
      }
    }
    Optional<Path> cell = workspace ? Optional.of(dir.resolve("cell.json")) : Optional.empty();
    if (Files.isRegularFile(dir.resolve("manifest.json"))) {
      return unpackedHandIn(dir, name, kind, programs, cell);
    }
    List<String> problems = List.of(workspace ? "a workspace folder, not a hand-in .zip" : "a folder of programs, not a hand-in .zip");
    return new Submission(name, kind, programs, cell, "", problems, Optional.empty(), Optional.empty());
  }

  /**
   * A hand-in unpacked by someone else (Gradescope unpacks an uploaded .zip): the manifest is
   * checked against the files as they are on disk.
   */
  private Submission unpackedHandIn(Path dir, String name, Submission.Kind kind, Path programs, Optional<Path> cell)
      throws IOException {
    Map<String, String> hashes = new LinkedHashMap<>();
    List<String> problems = new ArrayList<>();
    List<String> droppings = new ArrayList<>();
    long total = 0;
    try (java.util.stream.Stream<Path> s = Files.walk(dir, 3)) {
      for (Iterator<Path> it = s.iterator(); it.hasNext(); ) {
        Path p = it.next();
        if (!Files.isRegularFile(p, java.nio.file.LinkOption.NOFOLLOW_LINKS)) {
          continue;
        }
        String rel = dir.relativize(p).toString().replace('\\', '/');
        if (rel.equals("manifest.json")) {
          continue;
        }
        if (HandInDroppings.isDropping(rel)) {
          droppings.add(rel);
          continue;
        }
        if (hashes.size() >= limits.entries()) {
          return Submission.failed(name, kind, "more than " + limits.entries() + " files", Optional.empty());
        }
        long size = Files.size(p);
        total += size;
        if (size > limits.entryBytes() || total > limits.totalBytes()) {
          return Submission.failed(name, kind, "\"" + rel + "\" is too large (" + size + " bytes)", Optional.empty());
        }
        hashes.put(rel, sha256(Files.readAllBytes(p)));
      }
    }
    byte[] manifest;
    try {
      // Bounded and a regular file only: a FIFO named manifest.json must not block the grader.
      manifest = org.robotrun.io.BoundedFiles.read(dir.resolve("manifest.json"), limits.entryBytes(), "manifest files");
    } catch (org.robotrun.io.UnreadableFileException e) {
      return Submission.failed(name, kind, "manifest.json: " + e.getMessage(), Optional.empty());
    }
    String student = checkManifest(manifest, hashes, problems);
    return new Submission(name, kind, programs, cell, student, problems, Optional.empty(), Optional.empty(), droppings);
  }

  private Submission zip(Path file, String name) throws IOException {
    Path temp = Files.createTempDirectory("robotrun-grade-",
        PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rwx------")));
    Map<String, String> hashes = new LinkedHashMap<>();
    Map<String, byte[]> keep = new LinkedHashMap<>();
    List<String> droppings = new ArrayList<>();
    byte[] manifest = null;
    int entries = 0;
    long total = 0;
    try (ZipInputStream zin = new ZipInputStream(new BufferedInputStream(Files.newInputStream(file)), StandardCharsets.UTF_8)) {
      while (true) {
        ZipEntry e;
        try {
          e = zin.getNextEntry();
        } catch (IllegalArgumentException bad) {
          return Submission.failed(name, Submission.Kind.ZIP, "entry " + (entries + 1)
              + " of the zip has a file name that is not UTF-8; make the zip again with RobotRun's Hand in", Optional.of(temp));
        }
        if (e == null) {
          break;
        }
        if (++entries > limits.entries()) {
          return Submission.failed(name, Submission.Kind.ZIP, "the zip has more than " + limits.entries() + " entries",
              Optional.of(temp));
        }
        String entry = e.getName();
        Optional<String> bad = badName(entry);
        if (bad.isPresent()) {
          return Submission.failed(name, Submission.Kind.ZIP, "the zip entry \"" + printable(entry) + "\" " + bad.get(),
              Optional.of(temp));
        }
        if (e.isDirectory()) {
          continue;
        }
        if (hashes.containsKey(entry)) {
          return Submission.failed(name, Submission.Kind.ZIP, "the zip holds \"" + entry + "\" twice", Optional.of(temp));
        }
        byte[] bytes = readBounded(zin, entry, limits.totalBytes() - total);
        if (bytes == null) {
          return Submission.failed(name, Submission.Kind.ZIP, "the zip unpacks to more than " + mb(limits.totalBytes())
              + " (at \"" + entry + "\")", Optional.of(temp));
        }
        if (bytes.length > limits.entryBytes()) {
          return Submission.failed(name, Submission.Kind.ZIP, "\"" + entry + "\" unpacks to more than "
              + mb(limits.entryBytes()), Optional.of(temp));
        }
        total += bytes.length;
        if (HandInDroppings.isDropping(entry)) {
          droppings.add(entry);
          continue;
        }
        if (entry.equals("manifest.json")) {
          manifest = bytes;
          continue;
        }
        hashes.put(entry, sha256(bytes));
        // programs/X.LS (the first robot's) and programs/ROBOT/X.LS (a robot after the first).
        if (entry.equals("cell.json") || entry.startsWith("programs/") && isLs(entry)
            && entry.chars().filter(ch -> ch == '/').count() <= 2) {
          keep.put(entry, bytes);
        }
      }
    } catch (ZipException | EOFException e) {
      if (String.valueOf(e.getMessage()).contains("bad entry name")) {
        return Submission.failed(name, Submission.Kind.ZIP, "entry " + (entries + 1)
            + " of the zip has a file name that is not UTF-8; make the zip again with RobotRun's Hand in", Optional.of(temp));
      }
      return Submission.failed(name, Submission.Kind.ZIP, "not a readable zip file (" + describe(e) + ")", Optional.of(temp));
    }
    if (entries == 0) {
      return Submission.failed(name, Submission.Kind.ZIP, "not a zip file, or an empty one", Optional.of(temp));
    }
    // Written only once the whole zip has passed: a hostile zip costs no disk writes.
    Files.createDirectories(temp.resolve("programs"));
    for (Map.Entry<String, byte[]> e : keep.entrySet()) {
      Files.createDirectories(temp.resolve(e.getKey()).getParent());
      AtomicFiles.write(temp.resolve(e.getKey()), e.getValue());
    }
    List<String> problems = new ArrayList<>();
    String student = "";
    if (manifest == null) {
      problems.add("the zip has no manifest.json at its root (was it made with RobotRun's Hand in?)");
    } else {
      student = checkManifest(manifest, hashes, problems);
    }
    if (!hashes.containsKey("cell.json")) {
      problems.add("the zip has no cell.json at its root");
    }
    Optional<Path> cell = Files.isRegularFile(temp.resolve("cell.json")) ? Optional.of(temp.resolve("cell.json")) : Optional.empty();
    return new Submission(name, Submission.Kind.ZIP, temp.resolve("programs"), cell, student, problems, Optional.empty(),
        Optional.of(temp), droppings);
  }

  /** The manifest's student name; what is wrong with it goes to {@code problems}. */
  private static String checkManifest(byte[] manifest, Map<String, String> hashes, List<String> problems) {
    JsonNode m;
    try {
      m = JSON.readTree(manifest);
    } catch (IOException e) {
      problems.add("manifest.json is not valid JSON");
      return "";
    }
    if (m == null || !m.isObject()) {
      problems.add("manifest.json is not a JSON object");
      return "";
    }
    if (!m.path("format").isInt() || m.path("format").asInt() != 1) {
      problems.add("manifest.json: expected \"format\": 1");
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
    for (Map.Entry<String, String> e : hashes.entrySet()) {
      JsonNode h = files.get(e.getKey());
      if (h == null) {
        problems.add("\"" + e.getKey() + "\" is in the zip but not in manifest.json");
      } else if (!h.isTextual() || !h.asText().equals(e.getValue())) {
        problems.add("\"" + e.getKey() + "\" was changed after the hand-in was made (its SHA-256 does not match manifest.json)");
      }
    }
    for (Iterator<String> it = files.fieldNames(); it.hasNext(); ) {
      String f = it.next();
      if (!hashes.containsKey(f)) {
        problems.add("manifest.json lists \"" + printable(f) + "\", which is not in the zip");
      }
    }
    return student;
  }

  /** Reads an entry, at most {@code entryBytes + 1} bytes and at most {@code budget}; null past the budget. */
  private byte[] readBounded(InputStream in, String entry, long budget) throws IOException {
    long cap = Math.min(limits.entryBytes() + 1, budget + 1);
    ByteArrayOutputStream out = new ByteArrayOutputStream();
    byte[] buf = new byte[8192];
    long n = 0;
    int r;
    while ((r = in.read(buf, 0, (int) Math.min(buf.length, cap - n))) > 0) {
      out.write(buf, 0, r);
      n += r;
      if (n >= cap) {
        break;
      }
    }
    if (n > budget) {
      return null;
    }
    return out.toByteArray();
  }

  /** Why a zip entry name is refused, if it is. */
  static Optional<String> badName(String entry) {
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

  static boolean isLs(String name) {
    return name.length() > 3 && name.regionMatches(true, name.length() - 3, ".ls", 0, 3);
  }

  /** The hand-in writer's own hash (lowercase hex SHA-256), so both sides agree by construction. */
  private static String sha256(byte[] bytes) {
    return HandIn.sha256(bytes);
  }

  private static String printable(String s) {
    StringBuilder b = new StringBuilder();
    for (int i = 0; i < Math.min(s.length(), 100); i++) {
      char c = s.charAt(i);
      b.append(Character.isISOControl(c) ? '?' : c);
    }
    return s.length() > 100 ? b + "..." : b.toString();
  }

  private static String mb(long bytes) {
    return (bytes >> 20) + " MB";
  }

  static String describe(Throwable e) {
    return e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
  }
}
