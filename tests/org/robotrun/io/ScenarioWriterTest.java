package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import java.util.stream.Stream;
import org.assertj.core.api.recursive.comparison.RecursiveComparisonConfiguration;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.world.Scenario;

class ScenarioWriterTest {
  @TempDir Path dir;

  /** Degrees ↔ radians may move the last bit; everything else must be exact. */
  private static final RecursiveComparisonConfiguration CLOSE = RecursiveComparisonConfiguration.builder()
      .withComparatorForType((a, b) -> Math.abs(a - b) <= 1e-9 ? 0 : Double.compare(a, b), Double.class)
      .build();

  @Test
  void saveThenLoadGivesTheSameScenario() throws Exception {
    Path src = Files.createDirectories(dir.resolve("src"));
    Files.createDirectories(src.resolve("meshes"));
    Files.write(src.resolve("meshes/tri.stl"), binaryTriangle());
    Files.writeString(src.resolve("PICK.LS"), "/PROG PICK\n/MN\n/END\n");
    // The shipped example's own programs are replaced by one written here.
    String text = Files.readString(Path.of("scenarios/pick-and-place.json"))
        .replaceAll("\"programs\"\\s*:\\s*\\[[^\\]]*\\]\\s*,", "")
        .replaceAll("\"mainProgram\"\\s*:\\s*\"[^\"]*\"\\s*,", "")
        .replace("\"registers\"", """
            "programs": ["PICK.LS"], "mainProgram": "pick",
              "registers\"""")
        .replace("\"objects\": [", """
            "objects": [
                {"name": "bracket", "kind": "fixture", "shape": "mesh", "file": "meshes/tri.stl", "scale": 2,
                 "color": "#102030", "pose": {"x": 1, "y": 2, "z": 3, "w": 10, "p": -20, "r": 170}},""");
    Path original = Files.writeString(src.resolve("cell.json"), text);
    Scenario loaded = load(original);
    assertThat(loaded.programs()).hasSize(1);
    assertThat(loaded.mainProgram()).isEqualTo(Optional.of("PICK"));

    // Saved into another folder: paths are rewritten relative to it and still point at the same files.
    Path out = Files.createDirectories(dir.resolve("saved/deeper")).resolve("cell.json");
    Files.writeString(out, "old content");
    ScenarioWriter.write(loaded, out);
    assertThat(Files.readString(out)).contains("\"file\" : \"../../src/meshes/tri.stl\"");
    // Angles come back as typed, not as 9.999999999999998 after the trip through a matrix.
    assertThat(Files.readString(out)).contains("\"w\" : 10,", "\"p\" : -20,", "\"r\" : 170\n");
    Scenario reloaded = load(out);
    assertThat(reloaded).usingRecursiveComparison(CLOSE).isEqualTo(loaded);
    // Saving what was loaded gives the same bytes again.
    Path again = dir.resolve("saved/deeper/again.json");
    ScenarioWriter.write(reloaded, again);
    assertThat(Files.readString(again)).isEqualTo(Files.readString(out));
    // No temporary file is left behind.
    try (Stream<Path> files = Files.list(out.getParent())) {
      assertThat(files.map(p -> p.getFileName().toString()).toList()).containsExactlyInAnyOrder("cell.json", "again.json");
    }
  }

  @Test
  void everyExampleRoundTrips() throws Exception {
    try (Stream<Path> s = Files.list(Path.of("scenarios"))) {
      for (Path f : s.filter(p -> p.toString().endsWith(".json")).toList()) {
        Scenario a = load(f);
        Path out = dir.resolve(f.getFileName());
        ScenarioWriter.write(a, out);
        assertThat(load(out)).as(f.toString()).usingRecursiveComparison(CLOSE).isEqualTo(a);
      }
    }
  }

  private static Scenario load(Path f) {
    ScenarioLoad l = ScenarioReader.read(f);
    if (l instanceof ScenarioLoad.Failed failed) {
      throw new AssertionError(failed.message());
    }
    return ((ScenarioLoad.Loaded) l).scenario();
  }

  private static byte[] binaryTriangle() {
    ByteBuffer b = ByteBuffer.allocate(84 + 50).order(ByteOrder.LITTLE_ENDIAN);
    b.position(80);
    b.putInt(1);
    for (float v : new float[] {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0}) {
      b.putFloat(v);
    }
    b.putShort((short) 0);
    return b.array();
  }
}
