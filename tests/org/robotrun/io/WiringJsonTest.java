package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.world.Scenario;
import org.robotrun.world.Wiring;

/** The scenario's "wiring" section: wires between robots' outputs and inputs, and every bad one named with path and line. */
class WiringJsonTest {
  @TempDir Path dir;

  private static String cell(String wiring) {
    return """
        {
          "format": 1,
          "robots": [
            {"name": "loader", "model": "lrmate200id", "jointsDeg": [0, 0, 0, 0, -90, 0], "io": {"DO": 16}},
            {"name": "unloader", "model": "lrmate200id", "basePose": {"x": 900, "y": 0, "z": 0, "w": 0, "p": 0, "r": 180},
             "jointsDeg": [0, 0, 0, 0, -90, 0]}
          ],
          "objects": [],
          "wiring": [
        """ + wiring + """

          ]
        }
        """;
  }

  private Path write(String text) throws Exception {
    return Files.writeString(dir.resolve("cell.json"), text);
  }

  private static int lineOf(String text, String marker) {
    int at = text.indexOf(marker);
    assertThat(at).as("marker %s", marker).isNotNegative();
    return (int) text.substring(0, at).chars().filter(c -> c == '\n').count() + 1;
  }

  private List<ScenarioError> errors(String text) throws Exception {
    ScenarioLoad load = ScenarioReader.read(write(text));
    assertThat(load).isInstanceOf(ScenarioLoad.Failed.class);
    return ((ScenarioLoad.Failed) load).errors();
  }

  private ScenarioError onlyError(String text) throws Exception {
    List<ScenarioError> e = errors(text);
    assertThat(e).hasSize(1);
    return e.getFirst();
  }

  @Test
  void wiresAreReadAndWrittenBack() throws Exception {
    String text = cell("""
            {"from": "loader.DO[10]", "to": "unloader.DI[10]"},
            {"from": "unloader.DO[3]", "to": "loader.DI[7]"},
            {"from": "loader.DO[10]", "to": "loader.DI[2]"},
            {"from": "loader.go[2]", "to": "unloader.GI[1]"}""");
    Path file = write(text);
    Scenario s = ((ScenarioLoad.Loaded) ScenarioReader.read(file)).scenario();
    assertThat(s.wiring().wires()).extracting(w -> w.from() + "->" + w.to()).containsExactly(
        "loader.DO[10]->unloader.DI[10]", "unloader.DO[3]->loader.DI[7]", "loader.DO[10]->loader.DI[2]",
        "loader.GO[2]->unloader.GI[1]");
    ScenarioWriter.write(s, file);
    assertThat(((ScenarioLoad.Loaded) ScenarioReader.read(file)).scenario().wiring()).isEqualTo(s.wiring());
  }

  @Test
  void aCellWithoutWiringHasNone() throws Exception {
    String text = cell("").replace(",\n  \"wiring\": [\n\n  ]", "");
    assertThat(text).doesNotContain("wiring");
    assertThat(((ScenarioLoad.Loaded) ScenarioReader.read(write(text))).scenario().wiring()).isEqualTo(Wiring.NONE);
  }

  @Test
  void twoRobotNamesThatGiveOneProgramsFolderAreRefused() throws Exception {
    // "arm 1" and "ARM_1" both become programs/arm_1/ on a case-insensitive disk: their programs would mix.
    String text = """
        {
          "format": 1,
          "robots": [
            {"name": "first", "model": "lrmate200id"},
            {"name": "arm 1", "model": "lrmate200id", "basePose": {"x": 900, "y": 0, "z": 0, "w": 0, "p": 0, "r": 0}},
            {"name": "ARM_1", "model": "lrmate200id", "basePose": {"x": 0, "y": 900, "z": 0, "w": 0, "p": 0, "r": 0}}
          ],
          "objects": []
        }
        """;
    ScenarioError e = onlyError(text);
    assertThat(e.path()).isEqualTo("robots[2].name");
    assertThat(e.line()).isEqualTo(lineOf(text, "ARM_1"));
    assertThat(e.message()).contains("'arm 1'").contains("'ARM_1'").contains("programs folder");
  }

  @Test
  void anUnknownRobotIsNamedWithItsLine() throws Exception {
    String text = cell("""
            {"from": "loader.DO[1]", "to": "unloader.DI[1]"},
            {"from": "painter.DO[1]", "to": "unloader.DI[2]"}""");
    ScenarioError e = onlyError(text);
    assertThat(e.path()).isEqualTo("wiring[1].from");
    assertThat(e.line()).isEqualTo(lineOf(text, "painter"));
    assertThat(e.message()).contains("no robot named 'painter'").contains("loader, unloader");
  }

  @Test
  void aSignalBeyondTheRobotsIoSizeOrOfAnUnknownKindIsNamed() throws Exception {
    ScenarioError e = onlyError(cell("""
            {"from": "loader.DO[17]", "to": "unloader.DI[1]"}"""));
    assertThat(e.path()).isEqualTo("wiring[0].from");
    assertThat(e.message()).contains("loader.DO[17] does not exist").contains("DO[1..16]");
    ScenarioError kind = onlyError(cell("""
            {"from": "loader.XO[1]", "to": "unloader.DI[1]"}"""));
    assertThat(kind.message()).contains("unknown I/O kind 'XO'");
    ScenarioError shape = onlyError(cell("""
            {"from": "loader DO 1", "to": "unloader.DI[1]"}"""));
    assertThat(shape.message()).contains("expected a signal like \"robot1.DO[10]\"");
  }

  @Test
  void anInputDrivenByTwoOutputsIsNamedWithTheFirstDriver() throws Exception {
    String text = cell("""
            {"from": "loader.DO[1]", "to": "unloader.DI[5]"},
            {"from": "loader.DO[2]",
             "to": "unloader.DI[5]"}""");
    ScenarioError e = onlyError(text);
    assertThat(e.path()).isEqualTo("wiring[1].to");
    assertThat(e.line()).isEqualTo(lineOf(text, "\"loader.DO[2]\"") + 1);
    assertThat(e.message()).contains("unloader.DI[5] is already driven by loader.DO[1] (wiring[0])");
  }

  @Test
  void anOutputWiredToAnOutputOrFromAnInputIsRefused() throws Exception {
    ScenarioError toOutput = onlyError(cell("""
            {"from": "loader.DO[1]", "to": "unloader.DO[1]"}"""));
    assertThat(toOutput.path()).isEqualTo("wiring[0].to");
    assertThat(toOutput.message()).contains("unloader.DO[1] is an output").contains("a wire runs to an input");
    ScenarioError fromInput = onlyError(cell("""
            {"from": "loader.DI[1]", "to": "unloader.DI[1]"}"""));
    assertThat(fromInput.path()).isEqualTo("wiring[0].from");
    assertThat(fromInput.message()).contains("loader.DI[1] is an input").contains("a wire runs from an output");
    ScenarioError flag = onlyError(cell("""
            {"from": "loader.F[1]", "to": "unloader.DI[1]"}"""));
    assertThat(flag.message()).contains("is a flag");
  }

  /** Issue 26: UO[3] and SO[2] (driven by the controller), UI/SI/AI, AO were accepted as wire ends. */
  @Test
  void onlyDoRoGoDriveAndOnlyDiRiGiAreDriven() throws Exception {
    for (String to : List.of("UO[3]", "SO[2]", "UI[6]", "SI[1]", "AI[1]", "AO[1]", "F[1]")) {
      ScenarioError e = onlyError(cell("{\"from\": \"loader.DO[1]\", \"to\": \"unloader." + to + "\"}"));
      assertThat(e.path()).as(to).isEqualTo("wiring[0].to");
      assertThat(e.message()).as(to).contains("a wire runs to an input (DI, RI, GI)").doesNotContain(" is an input:");
    }
    assertThat(onlyError(cell("{\"from\": \"loader.DO[1]\", \"to\": \"unloader.UO[3]\"}")).message())
        .contains("unloader.UO[3] is a UOP output the controller drives").contains("would have two drivers");
    for (String from : List.of("UO[3]", "SO[2]", "UI[6]", "AI[1]", "AO[1]")) {
      ScenarioError e = onlyError(cell("{\"from\": \"loader." + from + "\", \"to\": \"unloader.DI[1]\"}"));
      assertThat(e.path()).as(from).isEqualTo("wiring[0].from");
      assertThat(e.message()).as(from).contains("a wire runs from an output (DO, RO, GO)");
    }
  }

  @Test
  void aLoopAndABitWiredToAGroupAreRefused() throws Exception {
    ScenarioError loop = onlyError(cell("""
            {"from": "loader.DO[1]", "to": "loader.DO[1]"}"""));
    assertThat(loop.message()).contains("an output wired to an output");
    ScenarioError width = onlyError(cell("""
            {"from": "loader.DO[1]", "to": "unloader.GI[1]"}"""));
    assertThat(width.path()).isEqualTo("wiring[0].to");
    assertThat(width.message()).contains("wire bits to bits");
  }

  @Test
  void severalBadWiresAreAllReportedAndUnknownFieldsNamed() throws Exception {
    List<ScenarioError> e = errors(cell("""
            {"from": "loader.DO[1]", "to": "ghost.DI[1]"},
            {"from": "loader.DO[2]", "to": "unloader.DI[2]", "via": "plc"},
            {"to": "unloader.DI[3]"}"""));
    assertThat(e).extracting(ScenarioError::path).containsExactlyInAnyOrder("wiring[0].to", "wiring[1].via",
        "wiring[2].from");
  }
}
