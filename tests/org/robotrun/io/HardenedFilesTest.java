package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.StringJoiner;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.world.TriangleMesh;

/** Reproducers from issue 18 for the scenario and STL readers, kept as regression tests. */
class HardenedFilesTest {
  @TempDir Path dir;

  private static final String HEAD = """
      {"format": 1, "robots": [{"name": "robot1", "model": "lrmate200id"}], "objects": [
      """;

  private static String box(String name, String extra) {
    return "{\"name\": \"" + name + "\", \"kind\": \"fixture\", \"shape\": \"box\", \"size\": {\"x\": 10, \"y\": 10, \"z\": 10},"
        + " \"pose\": {\"x\": 0, \"y\": 0, \"z\": 0}" + extra + "}";
  }

  private List<ScenarioError> errors(String text) throws Exception {
    Path f = Files.writeString(dir.resolve("s.json"), text);
    ScenarioLoad load = ScenarioReader.read(f);
    assertThat(load).isInstanceOf(ScenarioLoad.Failed.class);
    return ((ScenarioLoad.Failed) load).errors();
  }

  @Test
  void anEmptyObjectNameIsOneErrorAndNoObject() throws Exception {
    List<ScenarioError> e = errors(HEAD + box("", "") + "]}");
    assertThat(e).extracting(ScenarioError::message).containsExactly("expected a non-empty name");
  }

  @Test
  void parentLoopsAreFoundInLinearTime() throws Exception {
    // Method: a 30 000-long chain (quadratic checking took minutes), then the same with its end
    // pointing back at its start; the loop names each member once.
    int n = 30_000;
    StringJoiner chain = new StringJoiner(",\n");
    for (int i = 0; i < n; i++) {
      chain.add(box("o" + i, i == 0 ? "" : ", \"parent\": \"o" + (i - 1) + "\""));
    }
    Path ok = Files.writeString(dir.resolve("chain.json"), HEAD + chain + "]}");
    assertThat(ScenarioReader.read(ok)).isInstanceOf(ScenarioLoad.Loaded.class);
    ScenarioLoad.Loaded loaded = (ScenarioLoad.Loaded) ScenarioReader.read(ok);
    assertThat(loaded.scenario().world().poseInCell("o" + (n - 1)).z()).isEqualTo(0);

    StringJoiner loop = new StringJoiner(",\n");
    loop.add(box("a", ", \"parent\": \"c\""));
    loop.add(box("b", ", \"parent\": \"a\""));
    loop.add(box("c", ", \"parent\": \"b\""));
    loop.add(box("d", ", \"parent\": \"c\""));
    List<ScenarioError> e = errors(HEAD + loop + "]}");
    assertThat(e).extracting(ScenarioError::message).containsExactlyInAnyOrder(
        "parents form a loop through 'a'", "parents form a loop through 'b'", "parents form a loop through 'c'");
  }

  @Test
  void tooManyObjectsIsAClearLimit() throws Exception {
    StringJoiner many = new StringJoiner(",");
    for (int i = 0; i <= ScenarioReader.MAX_OBJECTS; i++) {
      many.add("{}");
    }
    List<ScenarioError> e = errors(HEAD + many + "]}");
    assertThat(e).extracting(ScenarioError::message).containsExactly("100001 objects; a scenario may hold at most 100000");
  }

  @Test
  void aFolderAsAMeshIsNotMissing() throws Exception {
    Files.createDirectories(dir.resolve("m.stl"));
    String mesh = "{\"name\": \"m\", \"kind\": \"fixture\", \"shape\": \"mesh\", \"file\": \"m.stl\","
        + " \"pose\": {\"x\": 0, \"y\": 0, \"z\": 0}}";
    List<ScenarioError> e = errors(HEAD + mesh + "]}");
    assertThat(e).hasSize(1);
    assertThat(e.getFirst().message()).contains("a folder, not a regular file").doesNotContain("not found");
  }

  private static String facet(String a, String b, String c) {
    return "facet normal 0 0 1\nouter loop\nvertex " + a + "\nvertex " + b + "\nvertex " + c + "\nendloop\nendfacet\n";
  }

  @Test
  void anAsciiVertexBeyondFloatRangeIsAFileError() throws Exception {
    Path f = Files.writeString(dir.resolve("big.stl"), "solid x\n" + facet("1e39 0 0", "0 1 0", "0 0 1") + "endsolid x\n");
    assertThatThrownBy(() -> StlReader.read(f, 1)).isInstanceOf(FileFormatException.class)
        .hasMessageStartingWith(f + ":4: vertex has a coordinate of 1.00000e+39 mm after scaling");
  }

  @Test
  void meshesFarOutsideTheCellAreRefused() throws Exception {
    Path f = Files.writeString(dir.resolve("far.stl"), "solid x\n" + facet("1e30 0 0", "0 1 0", "0 0 1") + "endsolid x\n");
    assertThatThrownBy(() -> StlReader.read(f, 1)).isInstanceOf(FileFormatException.class)
        .hasMessageContaining("meshes must lie within ±100000 mm");
    // in metres, scaled by 1000: 200 m is out too
    Path m = Files.writeString(dir.resolve("m.stl"), "solid x\n" + facet("200 0 0", "0 1 0", "0 0 1") + "endsolid x\n");
    assertThatThrownBy(() -> StlReader.read(m, 1000)).hasMessageContaining("a coordinate of 200000 mm");
    // binary too
    ByteBuffer b = ByteBuffer.allocate(84 + 50).order(ByteOrder.LITTLE_ENDIAN);
    b.position(80);
    b.putInt(1);
    b.position(84 + 12);
    b.putFloat(1e30f);
    Path bin = Files.write(dir.resolve("b.stl"), b.array());
    assertThatThrownBy(() -> StlReader.read(bin, 1)).hasMessageContaining("triangle 1 has a coordinate");
  }

  @Test
  void anAsciiSolidNamedWithAccentsIsReadAsAscii() throws Exception {
    String text = "solid Pièce_détachée\n" + facet("0 0 0", "1 0 0", "0 1 0") + "endsolid Pièce_détachée\n";
    Path f = Files.write(dir.resolve("accent.stl"), text.getBytes(StandardCharsets.UTF_8));
    TriangleMesh mesh = StlReader.read(f, 1);
    assertThat(mesh.triangleCount()).isEqualTo(1);
  }

  @Test
  void hexAndSuffixedNumbersAreNotNumbers() throws Exception {
    for (String n : new String[] {"0x1p3", "1d", "1f", "NaN", "Infinity"}) {
      Path f = Files.writeString(dir.resolve("n.stl"), "solid x\n" + facet(n + " 0 0", "0 1 0", "0 0 1") + "endsolid x\n");
      assertThatThrownBy(() -> StlReader.read(f, 1)).as(n).hasMessageContaining(":4: expected a finite number");
    }
    for (String n : new String[] {"0x1p3", "1d"}) {
      List<ScenarioError> e = errors(HEAD + box("a", "").replace("\"x\": 10", "\"x\": " + n) + "]}");
      assertThat(e).as(n).isNotEmpty();
    }
  }

  // ---- issue 26: names and recursive structures are bounded, never a StackOverflowError ----

  @Test
  void aMacroNameOfThousandsOfWordsIsOneErrorNotAStackOverflow() throws Exception {
    String words = String.join(" ", java.util.Collections.nCopies(5000, "W"));
    List<ScenarioError> e = errors("{\"format\": 1, \"robots\": [{\"name\": \"robot1\", \"model\": \"lrmate200id\","
        + " \"macros\": [{\"name\": \"" + words + "\", \"program\": \"P\"}]}]}");
    assertThat(e).extracting(ScenarioError::path, ScenarioError::message).containsExactly(org.assertj.core.groups.Tuple.tuple(
        "robots[0].macros[0].name", "a macro name is at most 36 characters, got 9999"));
    // as a workspace's cell.json (run --workspace, pendant --workspace, grade read it this way)
    Path cell = Files.writeString(dir.resolve("cell.json"), "{\"format\": 1, \"robots\": [{\"name\": \"robot1\","
        + " \"model\": \"lrmate200id\", \"macros\": [{\"name\": \"" + words.replace(" ", "_") + "\", \"program\": \"P\"}]}]}");
    assertThat(ScenarioReader.readCell(cell)).isInstanceOf(CellLoad.Failed.class);
    // a good name of several words still reads
    Path good = Files.writeString(dir.resolve("good.json"), "{\"format\": 1, \"robots\": [{\"name\": \"robot1\","
        + " \"model\": \"lrmate200id\", \"macros\": [{\"name\": \"HAND1 OPEN\", \"program\": \"HOPEN\"}]}]}");
    assertThat(ScenarioReader.read(good)).isInstanceOf(ScenarioLoad.Loaded.class);
    assertThat(errors("{\"format\": 1, \"robots\": [{\"name\": \"robot1\", \"model\": \"lrmate200id\","
        + " \"macros\": [{\"name\": \"HAND1  OPEN\", \"program\": \"P\"}]}]}")).extracting(ScenarioError::message)
        .singleElement().asString().startsWith("expected a macro name");
  }

  @Test
  void everyNameIsBoundedAndARobotCannotNameAProgramFile() throws Exception {
    String longName = "R".repeat(100_000);
    assertThat(errors("{\"format\": 1, \"robots\": [{\"name\": \"" + longName + "\", \"model\": \"lrmate200id\"}]}"))
        .extracting(ScenarioError::message).containsExactly("a name is at most 64 characters, got 100000");
    assertThat(errors(HEAD + box(longName, "") + "]}")).extracting(ScenarioError::message)
        .containsExactly("a name is at most 64 characters, got 100000");
    assertThat(errors("{\"format\": 1, \"name\": \"" + "W ".repeat(50_000) + "\", \"robots\": [{\"name\": \"r\","
        + " \"model\": \"lrmate200id\"}]}")).extracting(ScenarioError::message)
        .containsExactly("a scenario name is at most 200 characters, got 100000");
    List<ScenarioError> e = errors("{\"format\": 1, \"robots\": [{\"name\": \"robot1\", \"model\": \"lrmate200id\"},\n"
        + " {\"name\": \"LOADER.LS\", \"model\": \"lrmate200id\", \"basePose\": {\"x\": 1500, \"y\": 0, \"z\": 0}}]}");
    assertThat(e).extracting(ScenarioError::line, ScenarioError::path).containsExactly(
        org.assertj.core.groups.Tuple.tuple(2, "robots[1].name"));
    assertThat(e.get(0).message()).contains("programs folder programs/LOADER.LS/ would collide with a program file");
  }

  @Test
  void deeplyNestedJsonIsOneErrorNotAStackOverflow() throws Exception {
    List<ScenarioError> e = errors("{\"format\": 1, \"name\": " + "[".repeat(200_000) + "]".repeat(200_000) + "}");
    assertThat(e).hasSize(1);
    assertThat(e.get(0).message()).isEqualTo("not valid JSON at column 1022: nested more than 1000 levels deep");
  }

  @Test
  void staleTemporaryFilesOfAKilledSaveAreRemovedByTheWorkspacesWriterOnly() throws Exception {
    Path ws = dir.resolve("ws");
    var cell = ((ScenarioLoad.Loaded) ScenarioReader.read(Path.of("scenarios/empty-cell.json"))).scenario();
    Workspace.open(ws, cell).close();
    Path stale = Files.writeString(ws.resolve("programs/.MAIN.LS.0123456789ab.tmp"), "half a program");
    Path staleCell = Files.writeString(ws.resolve(".cell.json.a1b2c3d4e5f6.tmp"), "{");
    Path fresh = Files.writeString(ws.resolve("programs/.PICK.LS.ffffffffffff.tmp"), "being written now");
    Path mine = Files.writeString(ws.resolve("programs/.notes.tmp"), "not RobotRun's");
    java.nio.file.attribute.FileTime old = java.nio.file.attribute.FileTime.from(java.time.Instant.now().minusSeconds(3600));
    for (Path p : List.of(stale, staleCell, mine)) {
      Files.setLastModifiedTime(p, old);
    }
    Workspace.open(ws, cell, true).close();  // a reader leaves them
    assertThat(stale).exists();
    try (Workspace w = Workspace.open(ws, cell)) {
      assertThat(w.readOnly()).isFalse();
    }
    assertThat(stale).doesNotExist();
    assertThat(staleCell).doesNotExist();
    assertThat(fresh).exists();
    assertThat(mine).exists();
  }

  @Test
  void savedRegistersComeBackWithTheirTypeAndValue() throws Exception {
    Path f = Files.writeString(dir.resolve("cell.json"), "{\"format\": 1, \"robots\": [{\"name\": \"robot1\","
        + " \"model\": \"lrmate200id\"}], \"state\": {\"registers\": {\"1\": 7, \"2\": 2.0, \"3\": 2147483648,"
        + " \"4\": 1e-320, \"5\": 0.3333333333333333, \"6\": -4503599627370497, \"7\": 1.0E20}}}");
    CellLoad.Loaded first = (CellLoad.Loaded) ScenarioReader.readCell(f);
    Path again = dir.resolve("again/cell.json");
    Files.createDirectories(again.getParent());
    Files.writeString(again, ScenarioWriter.toJson(first.scenario(), first.state(), again.getParent()));
    CellLoad.Loaded second = (CellLoad.Loaded) ScenarioReader.readCell(again);
    var a = first.state().orElseThrow().registers();
    var b = second.state().orElseThrow().registers();
    assertThat(b).isEqualTo(a);
    assertThat(b.get(3)).isEqualTo(new SavedState.Register(2147483648.0, true));
    assertThat(b.get(4).value()).isEqualTo(1e-320);
    assertThat(b.get(4).integer()).isFalse();
    assertThat(b.get(5).value()).isEqualTo(1.0 / 3);
    assertThat(b.get(2)).isEqualTo(new SavedState.Register(2.0, false));
    assertThat(b.get(6)).isEqualTo(new SavedState.Register(-4503599627370497.0, true));
  }

  @Test
  void aSavedStateOfARobotTheCellLacksIsRefusedWithPathAndLine() throws Exception {
    List<ScenarioError> e = errors("{\"format\": 1, \"robots\": [{\"name\": \"robot1\", \"model\": \"lrmate200id\"}],\n"
        + " \"state\": {\"robots\": {\n \"ghost\": {\"registers\": {\"1\": 5}}}}}");
    assertThat(e).extracting(ScenarioError::line, ScenarioError::path).containsExactly(
        org.assertj.core.groups.Tuple.tuple(3, "state.robots.ghost"));
    assertThat(e.get(0).message()).contains("no robot 'ghost' after the first in this cell");
  }
}
