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
  /** programs/NAME.LS, or programs/ROBOT/NAME.LS for a later robot of the cell (no "..", no deeper folders). */
  private static final Pattern PROGRAM_ENTRY = HandInFiles.PROGRAM_ENTRY;
  /** The cell editor's other named scenarios: {@code scenarios/NAME.json}. */
  private static final Pattern SCENARIO_ENTRY = HandInFiles.SCENARIO_ENTRY;

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
    Path parent = zip.toAbsolutePath().getParent();
    if (parent == null || !Files.isDirectory(parent)) {
      throw new HandInException("cannot write " + zip + ": the folder " + parent + " does not exist");
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
    requireWithinLimits(workspaceDir, files, m);
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

  /**
   * Refuses a hand-in that {@code grade} and {@code run --workspace} would refuse (the one table,
   * {@link HandInFiles.Limits#DEFAULT}), before anything is written: what RobotRun writes is
   * always read back.
   */
  private static void requireWithinLimits(Path workspaceDir, Map<String, byte[]> files, Manifest m) throws HandInException {
    HandInFiles.Limits limits = HandInFiles.Limits.DEFAULT;
    if (files.size() + 1 > limits.entries()) {
      throw new HandInException("cannot hand in " + workspaceDir + ": it holds " + files.size() + " files; a hand-in holds"
          + " at most " + (limits.entries() - 1) + " besides its manifest (remove programs you no longer need)");
    }
    long total;
    try {
      total = manifestJson(m).getBytes(StandardCharsets.UTF_8).length;
    } catch (IOException e) {
      throw new HandInException("cannot hand in " + workspaceDir + ": " + Workspace.describe(e));
    }
    for (Map.Entry<String, byte[]> e : files.entrySet()) {
      if (e.getValue().length > limits.entryBytes()) {
        throw new HandInException("cannot hand in " + workspaceDir + ": " + e.getKey() + " is larger than "
            + HandInFiles.sizeText(limits.entryBytes()) + ", the most a hand-in file may be");
      }
      total += e.getValue().length;
    }
    if (total > limits.totalBytes()) {
      throw new HandInException("cannot hand in " + workspaceDir + ": its files come to more than "
          + HandInFiles.sizeText(limits.totalBytes()) + ", the most a hand-in may hold");
    }
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
   * after checking every name, size and checksum ({@link HandInFiles}: the same reader and
   * limits as {@code grade}). Nothing is written unless all of it passed; when writing fails,
   * what was written is the caller's to remove with {@code into}.
   *
   * @throws HandInException naming the zip (as the user gave it) and the entry at fault
   */
  public static Manifest unpack(Path zip, Path into) throws HandInException {
    String where = zip.toString();
    HandInFiles.Contents c;
    try {
      c = HandInFiles.readZip(zip, HandInFiles.Limits.DEFAULT);
    } catch (HandInException e) {
      throw new HandInException(where + ": " + e.getMessage());
    }
    HandInFiles.Verified v = HandInFiles.verify(c);
    if (!v.problems().isEmpty()) {
      throw new HandInException(where + ": " + v.problems().get(0));
    }
    Manifest m = parseManifest(where, c.manifest());
    try {
      HandInFiles.writeTo(c.files(), into);
    } catch (IOException e) {
      throw new HandInException("cannot unpack " + where + " into a temporary folder: " + Workspace.describe(e));
    }
    return m;
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
