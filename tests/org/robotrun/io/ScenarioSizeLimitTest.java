package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.math.Transform;
import org.robotrun.world.ObjectKind;
import org.robotrun.world.Rgb;
import org.robotrun.world.Scenario;
import org.robotrun.world.Shape;
import org.robotrun.world.World;
import org.robotrun.world.WorldObject;

/**
 * Issue 18: RobotRun never writes a scenario or {@code cell.json} it cannot read back. Indented
 * text more than doubles a big cell, so over the read limit objects go one a line; what is over
 * the limit even then is refused with a message, and the file on disk is left as it was.
 */
class ScenarioSizeLimitTest {
  @TempDir Path dir;

  private static Scenario withBoxes(int n) {
    Scenario base = load(Path.of("scenarios/pick-and-place.json"));
    List<WorldObject> objects = new ArrayList<>();
    for (int i = 0; i < n; i++) {
      objects.add(WorldObject.of("box" + i, ObjectKind.PART, new Shape.Box(20, 30, 40), new Rgb(200, 40, 40),
          Transform.fromRpy(600 + i % 100 * 25.5, -300 + i / 100 * 25.5, 10, 0, 0, Math.toRadians(i % 90)), Optional.empty()));
    }
    return new Scenario(base.name(), base.description(), base.robots(), new World(objects), base.programs(),
        base.mainProgram(), base.registers(), base.toolFrames(), base.userFrames(), base.camera(), base.onCollision())
        .withExtrasOf(base);
  }

  private static Scenario load(Path f) {
    ScenarioLoad l = ScenarioReader.read(f);
    if (l instanceof ScenarioLoad.Failed failed) {
      throw new AssertionError(failed.message());
    }
    return ((ScenarioLoad.Loaded) l).scenario();
  }

  @Test
  void overTheLimitIndentedACellIsWrittenOneObjectALineAndReadsBackTheSame() throws Exception {
    Scenario s = withBoxes(300);
    String pretty = ScenarioWriter.toJson(s, Optional.empty(), dir, Long.MAX_VALUE);
    long limit = pretty.getBytes(StandardCharsets.UTF_8).length - 1;
    String compact = ScenarioWriter.toJson(s, Optional.empty(), dir, limit);
    assertThat(compact.length()).isLessThan(pretty.length() * 6 / 10);
    List<String> objectLines = compact.lines().filter(l -> l.contains("\"name\":\"box")).toList();
    assertThat(objectLines).hasSize(300).allMatch(l -> l.startsWith("{\"name\":\"box") && l.contains("\"pose\":{"));
    // Under the limit, people get the indented text.
    assertThat(ScenarioWriter.toJson(s, Optional.empty(), dir, limit + 1)).isEqualTo(pretty);

    Path f = Files.writeString(dir.resolve("big.json"), compact);
    Scenario back = load(f);
    assertThat(back.world().objects()).hasSize(300);
    for (int i = 0; i < 300; i += 37) {
      WorldObject a = s.world().objects().get(i), b = back.world().objects().get(i);
      assertThat(b.name()).isEqualTo(a.name());
      assertThat(b.pose().distanceTo(a.pose())).isLessThan(1e-9);
      assertThat(b.pose().rotationAngleTo(a.pose())).isLessThan(1e-9);
    }
  }

  @Test
  void aHundredThousandBoxesFitTheReadLimit() throws Exception {
    // The case of the issue: `gui --scenario` of 100 000 boxes wrote a 26.9 MiB cell.json.
    Scenario s = withBoxes(ScenarioReader.MAX_OBJECTS);
    String json = ScenarioWriter.toJson(s, Optional.of(SavedState.fresh("2026-01-01T00:00:00Z")), dir);
    assertThat((long) json.getBytes(StandardCharsets.UTF_8).length).isLessThanOrEqualTo(ScenarioReader.MAX_FILE_BYTES);
  }

  @Test
  void aScenarioTooBigEvenOneObjectALineIsNeverWritten() throws Exception {
    Path f = Files.writeString(dir.resolve("cell.json"), "old");
    Scenario s = withBoxes(300);
    String compact = ScenarioWriter.toJson(s, Optional.empty(), dir, 1000);
    assertThatThrownBy(() -> ScenarioWriter.readableBytes(compact, f, 1000))
        .isInstanceOf(ScenarioWriter.TooLargeException.class)
        .hasMessageStartingWith("cell.json would be 0.")
        .hasMessageContaining("MiB, more than the 1000 bytes RobotRun reads back; nothing was written");
    assertThat(Files.readString(f)).isEqualTo("old");
  }

  @Test
  void aWorkspaceKeepsItsCellWhenTheNewOneWouldBeTooBigToOpen() throws Exception {
    Path wsDir = dir.resolve("ws");
    try (Workspace ws = Workspace.open(wsDir, withBoxes(3))) {
      Path cell = wsDir.resolve(Workspace.CELL);
      String before = Files.readString(cell);
      // Valid JSON, padded past the limit: what a cell of many large objects would come to.
      String huge = before.strip() + " ".repeat((int) ScenarioReader.MAX_FILE_BYTES) + "\n";
      assertThatThrownBy(() -> ws.save(new WorkspaceSnapshot(huge, Map.of())))
          .hasMessageContaining("cannot save " + cell)
          .hasMessageContaining("cell.json would be 16.0 MiB, more than the 16 MiB RobotRun reads back");
      assertThat(Files.readString(cell)).isEqualTo(before);
      try (var files = Files.list(wsDir)) {
        assertThat(files.map(p -> p.getFileName().toString()).filter(n -> n.contains("tmp"))).isEmpty();
      }
    }
  }
}
