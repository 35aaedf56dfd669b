package org.robotrun.io;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.core.util.DefaultIndenter;
import com.fasterxml.jackson.core.util.DefaultPrettyPrinter;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.HexFormat;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipInputStream;
import java.util.zip.ZipOutputStream;

/**
 * A hand-in: one {@code .zip} of a workspace whose root holds {@code manifest.json},
 * {@code cell.json}, {@code programs/*.LS}, in a cell of several robots the later robots'
 * {@code programs/ROBOT/*.LS}, and the other named scenarios {@code scenarios/*.json}
 * (docs/workspace.md). The manifest names the
 * student as typed, the workspace's creation and last-change times, the RobotRun version, the
 * scenario's name and the SHA-256 of every other file in the zip.
 *
 * <p>Reading is defensive, since a zip comes from someone else: only those names are accepted
 * (no folders but one level of robot folders under {@code programs/}, no {@code ..}, no absolute
 * paths), sizes are counted as the bytes arrive
 * (not taken from the headers), and every file must match the manifest's checksum.
 */
public final class HandIn {
  public static final String MANIFEST = "manifest.json";
  public static final int FORMAT = 1;
  /** Largest zip read, and largest total of its unpacked files. */
  public static final long MAX_TOTAL_BYTES = 64L << 20;
  /** Largest single file inside. */
  public static final long MAX_ENTRY_BYTES = 16L << 20;
  /** Most files inside. */
  public static final int MAX_ENTRIES = 2000;
  /** programs/NAME.LS, or programs/ROBOT/NAME.LS for a later robot of the cell (no "..", no deeper folders). */
  private static final Pattern PROGRAM_ENTRY = Pattern.compile(
      "programs/(?:[A-Za-z0-9_][A-Za-z0-9_.\\-]{0,63}/)?[A-Za-z0-9_][A-Za-z0-9_.\\-]{0,63}\\.(?i:ls)");
  /** The folder of a later robot's programs. */
  private static final Pattern ROBOT_FOLDER = Pattern.compile("programs/[A-Za-z0-9_][A-Za-z0-9_.\\-]{0,63}/");
  /** The cell editor's other named scenarios: {@code scenarios/NAME.json}. */
  private static final Pattern SCENARIO_ENTRY = Pattern.compile(Workspace.SCENARIOS + "/" + Workspace.SCENARIO_FILE.pattern());

  private HandIn() {}

  /** What a hand-in's manifest says. */
  public record Manifest(String student, String created, String modified, String robotrunVersion, String scenario,
      Map<String, String> files) {}

  /**
   * Writes the hand-in of the workspace in {@code workspaceDir} to {@code zip}.
   *
   * @param replace whether an existing {@code zip} may be replaced (the user said so)
   * @throws HandInException when the name is empty, the target exists and {@code replace} is false,
   *     or a file cannot be read or written
   */
  public static Manifest write(Path workspaceDir, Path zip, String student, String robotrunVersion, boolean replace)
      throws HandInException {
    String name = student == null ? "" : student.strip();
    if (name.isEmpty()) {
      throw new HandInException("type your name: the hand-in needs the student's name");
    }
    if (name.length() > 200 || name.chars().anyMatch(Character::isISOControl)) {
      throw new HandInException("the name must be one line of at most 200 characters");
    }
    if (Files.isDirectory(zip)) {
      throw new HandInException(zip + " is a folder: give a file name ending in .zip");
    }
    if (Files.exists(zip) && !replace) {
      throw new HandInException(zip + " already exists: choose another name, or confirm that it should be replaced");
    }
    Map<String, byte[]> files = new TreeMap<>();
    FileTime newest = FileTime.fromMillis(0);
    try {
      Path cell = workspaceDir.resolve(Workspace.CELL);
      files.put(Workspace.CELL, BoundedFiles.read(cell, ScenarioReader.MAX_FILE_BYTES, "cell files"));
      newest = Files.getLastModifiedTime(cell);
      Path programs = workspaceDir.resolve(Workspace.PROGRAMS);
      if (Files.isDirectory(programs)) {
        List<Path> found = new java.util.ArrayList<>();
        try (Stream<Path> s = Files.list(programs)) {
          for (Path f : s.sorted().toList()) {
            if (Files.isRegularFile(f)) {
              found.add(f);
            } else if (Files.isDirectory(f)) {
              // a later robot's programs (programs/ROBOT/)
              try (Stream<Path> inner = Files.list(f)) {
                inner.filter(Files::isRegularFile).sorted().forEach(found::add);
              }
            }
          }
        }
        for (Path f : found) {
          String entry = Workspace.PROGRAMS + "/" + programs.relativize(f).toString().replace('\\', '/');
          if (!PROGRAM_ENTRY.matcher(entry).matches()) {
            continue;  // not a program (an editor's backup, a stray file)
          }
          files.put(entry, BoundedFiles.read(f, LsReader.MAX_FILE_BYTES, ".LS programs"));
          FileTime t = Files.getLastModifiedTime(f);
          newest = t.compareTo(newest) > 0 ? t : newest;
        }
      }
      Path scenarios = workspaceDir.resolve(Workspace.SCENARIOS);
      if (Files.isDirectory(scenarios)) {
        try (Stream<Path> s = Files.list(scenarios)) {
          for (Path f : s.filter(Files::isRegularFile).sorted().toList()) {
            String entry = Workspace.SCENARIOS + "/" + f.getFileName();
            if (SCENARIO_ENTRY.matcher(entry).matches()) {
              files.put(entry, BoundedFiles.read(f, ScenarioReader.MAX_FILE_BYTES, "scenario files"));
            }
          }
        }
      }
    } catch (IOException e) {
      throw new HandInException("cannot read the workspace " + workspaceDir + ": " + Workspace.describe(e));
    }
    String scenario = "";
    String created = "";
    if (ScenarioReader.readCell(workspaceDir.resolve(Workspace.CELL)) instanceof CellLoad.Loaded l) {
      scenario = l.scenario().name();
      created = l.state().map(SavedState::created).orElse("");
    }
    String modified = newest.toInstant().truncatedTo(ChronoUnit.SECONDS).toString();
    if (created.isEmpty()) {
      created = modified;
    }
    Map<String, String> sums = new LinkedHashMap<>();
    files.forEach((entry, bytes) -> sums.put(entry, sha256(bytes)));
    Manifest m = new Manifest(name, created, modified, robotrunVersion, scenario, sums);
    try {
      ByteArrayOutputStream buf = new ByteArrayOutputStream();
      try (ZipOutputStream z = new ZipOutputStream(buf, StandardCharsets.UTF_8)) {
        put(z, MANIFEST, manifestJson(m).getBytes(StandardCharsets.UTF_8));
        for (Map.Entry<String, byte[]> e : files.entrySet()) {
          put(z, e.getKey(), e.getValue());
        }
      }
      AtomicFiles.write(zip, buf.toByteArray());
    } catch (IOException e) {
      throw new HandInException("cannot write " + zip + ": " + Workspace.describe(e));
    }
    return m;
  }

  private static void put(ZipOutputStream z, String name, byte[] bytes) throws IOException {
    ZipEntry e = new ZipEntry(name);
    z.putNextEntry(e);
    z.write(bytes);
    z.closeEntry();
  }

  static String manifestJson(Manifest m) throws IOException {
    StringWriter text = new StringWriter();
    try (JsonGenerator g = new JsonFactory().createGenerator(text)) {
      g.setPrettyPrinter(new DefaultPrettyPrinter().withObjectIndenter(new DefaultIndenter("  ", "\n")));
      g.writeStartObject();
      g.writeNumberField("format", FORMAT);
      g.writeStringField("student", m.student());
      g.writeStringField("created", m.created());
      g.writeStringField("modified", m.modified());
      g.writeStringField("robotrunVersion", m.robotrunVersion());
      g.writeStringField("scenario", m.scenario());
      g.writeObjectFieldStart("files");
      for (Map.Entry<String, String> e : m.files().entrySet()) {
        g.writeStringField(e.getKey(), e.getValue());
      }
      g.writeEndObject();
      g.writeEndObject();
    }
    return text + "\n";
  }

  /** Lowercase hex SHA-256. */
  public static String sha256(byte[] bytes) {
    try {
      return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(bytes));
    } catch (NoSuchAlgorithmException e) {
      throw new IllegalStateException("every Java has SHA-256", e);
    }
  }

  /**
   * Unpacks a hand-in into the empty folder {@code into} (a workspace to open read-only),
   * after checking every name, size and checksum.
   *
   * @throws HandInException naming the zip and the entry at fault
   */
  public static Manifest unpack(Path zip, Path into) throws HandInException {
    String where = zip.toString();
    Map<String, byte[]> files = new TreeMap<>();
    byte[] manifestBytes = null;
    try {
      long size;
      try {
        size = BoundedFiles.requireRegularFile(zip);  // a FIFO or a device is named, never opened
      } catch (UnreadableFileException e) {
        throw new HandInException(where + ": " + e.getMessage());
      }
      if (size > MAX_TOTAL_BYTES) {
        throw new HandInException(where + ": the file is " + size + " bytes; hand-ins are limited to " + MAX_TOTAL_BYTES);
      }
      long total = 0;
      int count = 0;
      try (InputStream in = Files.newInputStream(zip); ZipInputStream z = new ZipInputStream(in, StandardCharsets.UTF_8)) {
        ZipEntry e;
        while ((e = z.getNextEntry()) != null) {
          if (++count > MAX_ENTRIES) {
            throw new HandInException(where + ": more than " + MAX_ENTRIES + " entries");
          }
          String name = e.getName();
          if (HandInDroppings.isDropping(name)) {
            continue;  // __MACOSX/, .DS_Store and the like: not part of the hand-in
          }
          if (e.isDirectory() && (name.equals(Workspace.PROGRAMS + "/") || ROBOT_FOLDER.matcher(name).matches()
              || name.equals(Workspace.SCENARIOS + "/"))) {
            continue;
          }
          if (!name.equals(MANIFEST) && !name.equals(Workspace.CELL) && !PROGRAM_ENTRY.matcher(name).matches()
              && !SCENARIO_ENTRY.matcher(name).matches()) {
            throw new HandInException(where + ": unexpected entry \"" + name
                + "\" (a hand-in holds manifest.json, cell.json, programs/NAME.LS, programs/ROBOT/NAME.LS and"
                + " scenarios/NAME.json only)");
          }
          if (files.containsKey(name) || (name.equals(MANIFEST) && manifestBytes != null)) {
            throw new HandInException(where + ": entry \"" + name + "\" is in the zip twice");
          }
          byte[] bytes = readBounded(z, where, name);
          total += bytes.length;
          if (total > MAX_TOTAL_BYTES) {
            throw new HandInException(where + ": unpacks to more than " + MAX_TOTAL_BYTES + " bytes");
          }
          if (name.equals(MANIFEST)) {
            manifestBytes = bytes;
          } else {
            files.put(name, bytes);
          }
        }
      }
    } catch (java.util.zip.ZipException e) {
      throw new HandInException(where + ": not a readable zip (" + e.getMessage() + ")");
    } catch (java.nio.file.NoSuchFileException e) {
      throw new HandInException(where + ": no such file");
    } catch (IOException e) {
      throw new HandInException(where + ": cannot read (" + Workspace.describe(e) + ")");
    }
    if (manifestBytes == null) {
      throw new HandInException(where + ": no manifest.json (is this a RobotRun hand-in?)");
    }
    Manifest m = parseManifest(where, manifestBytes);
    for (Map.Entry<String, String> e : m.files().entrySet()) {
      byte[] bytes = files.get(e.getKey());
      if (bytes == null) {
        throw new HandInException(where + ": manifest.json: files.\"" + e.getKey() + "\" is listed but not in the zip");
      }
      if (!sha256(bytes).equals(e.getValue().toLowerCase(Locale.ROOT))) {
        throw new HandInException(where + ": " + e.getKey() + " does not match its SHA-256 in manifest.json (changed after hand-in?)");
      }
    }
    for (String name : files.keySet()) {
      if (!m.files().containsKey(name)) {
        throw new HandInException(where + ": " + name + " is in the zip but not listed in manifest.json");
      }
    }
    if (!files.containsKey(Workspace.CELL)) {
      throw new HandInException(where + ": no cell.json");
    }
    try {
      Files.createDirectories(into.resolve(Workspace.PROGRAMS));
      for (Map.Entry<String, byte[]> e : files.entrySet()) {
        Files.createDirectories(into.resolve(e.getKey()).getParent());
        AtomicFiles.write(into.resolve(e.getKey()), e.getValue());
      }
    } catch (IOException e) {
      throw new HandInException("cannot unpack " + where + " into " + into + ": " + Workspace.describe(e));
    }
    return m;
  }

  private static byte[] readBounded(ZipInputStream z, String where, String name) throws IOException, HandInException {
    ByteArrayOutputStream out = new ByteArrayOutputStream();
    byte[] buf = new byte[8192];
    int n;
    long total = 0;
    while ((n = z.read(buf)) > 0) {
      total += n;
      if (total > MAX_ENTRY_BYTES) {
        throw new HandInException(where + ": " + name + " unpacks to more than " + MAX_ENTRY_BYTES + " bytes");
      }
      out.write(buf, 0, n);
    }
    return out.toByteArray();
  }

  private static Manifest parseManifest(String where, byte[] bytes) throws HandInException {
    JsonNode root;
    try {
      root = new ObjectMapper().readTree(bytes);
    } catch (IOException e) {
      throw new HandInException(where + ": manifest.json is not valid JSON (" + e.getMessage().lines().findFirst().orElse("") + ")");
    }
    if (root == null || !root.isObject()) {
      throw new HandInException(where + ": manifest.json: expected a JSON object");
    }
    JsonNode format = root.get("format");
    if (format == null || !format.isInt()) {
      throw new HandInException(where + ": manifest.json: format: expected the integer " + FORMAT);
    }
    if (format.intValue() != FORMAT) {
      throw new HandInException(where + ": manifest.json: format " + format.intValue() + " is newer than this RobotRun reads ("
          + FORMAT + "); update RobotRun");
    }
    JsonNode files = root.get("files");
    if (files == null || !files.isObject()) {
      throw new HandInException(where + ": manifest.json: files: expected an object of file name to SHA-256");
    }
    Map<String, String> sums = new LinkedHashMap<>();
    for (Iterator<Map.Entry<String, JsonNode>> it = files.fields(); it.hasNext(); ) {
      Map.Entry<String, JsonNode> e = it.next();
      if (!e.getValue().isTextual() || !e.getValue().asText().matches("[0-9a-fA-F]{64}")) {
        throw new HandInException(where + ": manifest.json: files.\"" + e.getKey() + "\": expected a SHA-256 in hex");
      }
      sums.put(e.getKey(), e.getValue().asText());
    }
    return new Manifest(text(root, "student"), text(root, "created"), text(root, "modified"),
        text(root, "robotrunVersion"), text(root, "scenario"), sums);
  }

  private static String text(JsonNode root, String field) {
    JsonNode v = root.get(field);
    return v != null && v.isTextual() ? v.asText() : "";
  }

  /** Now, for a manifest (seconds, UTC). */
  static String now() {
    return Instant.now().truncatedTo(ChronoUnit.SECONDS).toString();
  }
}
