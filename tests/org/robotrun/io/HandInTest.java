package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.zip.ZipEntry;
import java.util.zip.ZipFile;
import java.util.zip.ZipOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.program.Instruction;
import org.robotrun.program.Program;

/** The hand-in zip: manifest as CONTRACTS.md item 2 says, no silent clobbering, defensive reading. */
class HandInTest {
  private static Path workspace(Path tmp) throws Exception {
    Path dir = tmp.resolve("ws");
    var sc = ((ScenarioLoad.Loaded) ScenarioReader.read(Path.of("scenarios/pick-and-place.json"))).scenario();
    sc = new org.robotrun.world.Scenario(sc.name(), sc.description(), sc.robots(), sc.world(), List.of(), sc.mainProgram(),
        sc.registers(), sc.toolFrames(), sc.userFrames(), sc.camera(), sc.onCollision());
    Workspace.open(dir, sc).close();
    Files.writeString(dir.resolve("programs/MAIN.LS"), LsWriter.write(Program.of("MAIN", List.of(new Instruction.Comment("hi")))));
    return dir;
  }

  @Test
  void theZipHoldsTheManifestCellAndProgramsWithTheirChecksums(@TempDir Path tmp) throws Exception {
    Path dir = workspace(tmp);
    Path zip = tmp.resolve("out.zip");
    HandIn.write(dir, zip, "  Ada Lovelace ", "0.1.0-SNAPSHOT", false);
    try (ZipFile z = new ZipFile(zip.toFile())) {
      assertThat(z.stream().map(ZipEntry::getName)).containsExactly("manifest.json", "cell.json", "programs/MAIN.LS");
      JsonNode m = new ObjectMapper().readTree(z.getInputStream(z.getEntry("manifest.json")));
      assertThat(m.get("format").intValue()).isEqualTo(1);
      assertThat(m.get("student").asText()).isEqualTo("Ada Lovelace");
      assertThat(m.get("robotrunVersion").asText()).isEqualTo("0.1.0-SNAPSHOT");
      assertThat(m.get("scenario").asText()).isEqualTo("Pick and place");
      assertThat(m.get("created").asText()).matches("\\d{4}-\\d\\d-\\d\\dT\\d\\d:\\d\\d:\\d\\dZ");
      assertThat(m.get("modified").asText()).matches("\\d{4}-\\d\\d-\\d\\dT\\d\\d:\\d\\d:\\d\\dZ");
      for (String f : List.of("cell.json", "programs/MAIN.LS")) {
        byte[] bytes = z.getInputStream(z.getEntry(f)).readAllBytes();
        assertThat(bytes).isEqualTo(Files.readAllBytes(dir.resolve(f)));
        assertThat(m.get("files").get(f).asText()).isEqualTo(HandIn.sha256(bytes)).matches("[0-9a-f]{64}");
      }
      assertThat(m.get("files").size()).isEqualTo(2);
    }
    Path back = tmp.resolve("back");
    HandIn.Manifest read = HandIn.unpack(zip, back);
    assertThat(read.student()).isEqualTo("Ada Lovelace");
    assertThat(Files.readAllBytes(back.resolve("programs/MAIN.LS"))).isEqualTo(Files.readAllBytes(dir.resolve("programs/MAIN.LS")));
  }

  @Test
  void anExistingFileIsNotReplacedUnlessAsked(@TempDir Path tmp) throws Exception {
    Path dir = workspace(tmp);
    Path zip = tmp.resolve("out.zip");
    Files.writeString(zip, "someone else's file");
    assertThatThrownBy(() -> HandIn.write(dir, zip, "Ada", "v", false)).isInstanceOf(HandInException.class)
        .hasMessageContaining("already exists");
    assertThat(Files.readString(zip)).isEqualTo("someone else's file");
    HandIn.write(dir, zip, "Ada", "v", true);
    assertThat(Files.size(zip)).isGreaterThan(100);
    assertThatThrownBy(() -> HandIn.write(dir, tmp.resolve("x.zip"), " ", "v", false)).hasMessageContaining("name");
  }

  private static Path zipOf(Path tmp, Map<String, byte[]> entries) throws Exception {
    ByteArrayOutputStream buf = new ByteArrayOutputStream();
    try (ZipOutputStream z = new ZipOutputStream(buf)) {
      for (var e : entries.entrySet()) {
        z.putNextEntry(new ZipEntry(e.getKey()));
        z.write(e.getValue());
        z.closeEntry();
      }
    }
    Path zip = tmp.resolve("evil.zip");
    Files.write(zip, buf.toByteArray());
    return zip;
  }

  private static byte[] manifest(Map<String, byte[]> files) {
    StringBuilder sb = new StringBuilder("{\"format\":1,\"student\":\"x\",\"files\":{");
    String sep = "";
    for (var e : files.entrySet()) {
      sb.append(sep).append('"').append(e.getKey()).append("\":\"").append(HandIn.sha256(e.getValue())).append('"');
      sep = ",";
    }
    return sb.append("}}").toString().getBytes(StandardCharsets.UTF_8);
  }

  @Test
  void pathsOutsideTheWorkspaceAreRefused(@TempDir Path tmp) throws Exception {
    for (String evil : List.of("../escape.LS", "programs/../../escape.LS", "/etc/passwd", "programs/sub/deeper/X.LS",
        "programs/.hidden/X.LS", "programs/../x/X.LS", "C:\\x.LS", "other.txt")) {
      Map<String, byte[]> files = new LinkedHashMap<>();
      files.put("cell.json", "{}".getBytes(StandardCharsets.UTF_8));
      files.put(evil, "x".getBytes(StandardCharsets.UTF_8));
      Map<String, byte[]> entries = new LinkedHashMap<>();
      entries.put("manifest.json", manifest(files));
      entries.putAll(files);
      Path into = tmp.resolve("into");
      assertThatThrownBy(() -> HandIn.unpack(zipOf(tmp, entries), into)).as(evil).isInstanceOf(HandInException.class)
          .hasMessageMatching(".*(unexpected entry|points outside the zip|is not a relative path inside the zip).*");
      assertThat(tmp.resolve("escape.LS")).doesNotExist();
      assertThat(into).doesNotExist();
    }
  }

  @Test
  void aChangedFileOrAMissingManifestIsRefused(@TempDir Path tmp) throws Exception {
    Map<String, byte[]> files = new LinkedHashMap<>();
    files.put("cell.json", "{}".getBytes(StandardCharsets.UTF_8));
    Map<String, byte[]> entries = new LinkedHashMap<>();
    entries.put("manifest.json", manifest(files));
    entries.put("cell.json", "{ }".getBytes(StandardCharsets.UTF_8));
    assertThatThrownBy(() -> HandIn.unpack(zipOf(tmp, entries), tmp.resolve("a"))).hasMessageContaining("SHA-256");
    assertThatThrownBy(() -> HandIn.unpack(zipOf(tmp, files), tmp.resolve("b"))).hasMessageContaining("no manifest.json");
    Path notZip = tmp.resolve("no.zip");
    Files.writeString(notZip, "hello");
    assertThatThrownBy(() -> HandIn.unpack(notZip, tmp.resolve("c"))).isInstanceOf(HandInException.class);
  }

  @Test
  void aZipBombIsStoppedByCountingBytes(@TempDir Path tmp) throws Exception {
    Map<String, byte[]> entries = new LinkedHashMap<>();
    entries.put("cell.json", new byte[(int) org.robotrun.io.HandInFiles.Limits.DEFAULT.entryBytes() + 1]);  // deflates to a few KiB
    Path zip = zipOf(tmp, entries);
    assertThat(Files.size(zip)).isLessThan(100_000);
    assertThatThrownBy(() -> HandIn.unpack(zip, tmp.resolve("x"))).hasMessageContaining("more than");
  }
}
