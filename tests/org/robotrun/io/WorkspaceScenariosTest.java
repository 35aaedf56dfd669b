package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.zip.ZipEntry;
import java.util.zip.ZipFile;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.world.Scenario;
import org.robotrun.world.World;

/** The cell editor's other named scenarios: saved in scenarios/NAME.json, read back, handed in. */
class WorkspaceScenariosTest {
  private static Scenario cell() {
    return ((ScenarioLoad.Loaded) ScenarioReader.read(Path.of("scenarios/pick-and-place.json"))).scenario();
  }

  private static Scenario named(String name, World world) {
    Scenario s = cell();
    return new Scenario(name, "exercise " + name, s.robots(), world, List.of(), Optional.empty(), s.registers(),
        s.toolFrames(), s.userFrames(), s.camera(), s.onCollision(), Optional.of("T2"));
  }

  private static WorkspaceSnapshot snapshot(Workspace ws, List<Scenario> others) throws Exception {
    return new WorkspaceSnapshot(ScenarioWriter.toJson(ws.scenario(), Optional.of(SavedState.fresh("")), ws.folder()),
        Map.of(), Optional.of(others));
  }

  @Test
  void otherScenariosAreSavedOneFileEachAndComeBackWithTheirContent(@TempDir Path tmp) throws Exception {
    Path dir = tmp.resolve("ws");
    Scenario practice = named("practice", World.empty());
    Scenario odd = named("Exam 2/b", cell().world());
    try (Workspace ws = Workspace.open(dir, cell())) {
      assertThat(ws.otherScenarios()).isEmpty();
      assertThat(ws.save(snapshot(ws, List.of(practice, odd))))
          .contains(dir.resolve("scenarios/practice.json"), dir.resolve("scenarios/Exam_2_b.json"));
    }
    try (Workspace ws = Workspace.open(dir, cell())) {
      assertThat(ws.problems()).isEmpty();
      // file-name order; the names and everything else as saved, not the file names
      assertThat(ws.otherScenarios()).extracting(Scenario::name).containsExactly("Exam 2/b", "practice");
      Scenario back = ws.otherScenarios().get(1);
      assertThat(back.description()).isEqualTo("exercise practice");
      assertThat(back.mode()).contains("T2");
      assertThat(back.world().objects()).isEmpty();
      assertThat(ws.otherScenarios().get(0).world().objects()).hasSameSizeAs(cell().world().objects());
      // nothing changed: nothing written
      assertThat(ws.save(snapshot(ws, ws.otherScenarios()))).isEmpty();
      // one deleted in the editor: its file goes
      ws.save(snapshot(ws, List.of(ws.otherScenarios().get(1))));
      assertThat(dir.resolve("scenarios/Exam_2_b.json")).doesNotExist();
      assertThat(dir.resolve("scenarios/practice.json")).exists();
      // a save that does not know the scenarios (run, pendant) leaves them alone
      ws.save(new WorkspaceSnapshot(snapshot(ws, List.of()).cellJson(), Map.of()));
      assertThat(dir.resolve("scenarios/practice.json")).exists();
    }
  }

  @Test
  void namesThatGiveTheSameFileGetNumbersAndKeepTheirOwnNames(@TempDir Path tmp) throws Exception {
    var files = Workspace.scenarioFileNames(List.of(named("Lab", World.empty()), named("lab", World.empty()),
        named(".hidden", World.empty()), named("", World.empty())), java.util.Set.of("LAB-2.json"));
    assertThat(files.keySet()).containsExactly("Lab.json", "lab-3.json", "_.hidden.json", "unnamed.json");
    files.keySet().forEach(f -> assertThat(Workspace.SCENARIO_FILE.matcher(f).matches()).as(f).isTrue());
  }

  @Test
  void anUnreadableScenarioFileIsReportedAndKeptAndAnotherOfItsNameGoesBeside(@TempDir Path tmp) throws Exception {
    Path dir = tmp.resolve("ws");
    Workspace.open(dir, cell()).close();
    Files.createDirectories(dir.resolve("scenarios"));
    Path bad = dir.resolve("scenarios/lab.json");
    Files.writeString(bad, "{ \"format\": 1, \"robots\": 3 }");
    try (Workspace ws = Workspace.open(dir, cell())) {
      assertThat(String.join("\n", ws.problems())).contains("lab.json").contains("robots").contains("kept as it is");
      assertThat(ws.otherScenarios()).isEmpty();
      ws.save(snapshot(ws, List.of(named("lab", World.empty()))));
    }
    assertThat(Files.readString(bad)).isEqualTo("{ \"format\": 1, \"robots\": 3 }");
    assertThat(dir.resolve("scenarios/lab-2.json")).exists();
  }

  @Test
  void aFileOfTheActiveScenarioLeftByAnInterruptedSwitchIsDroppedNotDoubled(@TempDir Path tmp) throws Exception {
    Path dir = tmp.resolve("ws");
    try (Workspace ws = Workspace.open(dir, cell())) {
      ws.save(snapshot(ws, List.of(cell(), named("practice", World.empty()))));
    }
    assertThat(dir.resolve("scenarios/Pick_and_place.json")).exists();
    try (Workspace ws = Workspace.open(dir, cell())) {
      assertThat(ws.problems()).isEmpty();
      assertThat(ws.otherScenarios()).extracting(Scenario::name).containsExactly("practice");
      ws.save(snapshot(ws, ws.otherScenarios()));
    }
    assertThat(dir.resolve("scenarios/Pick_and_place.json")).doesNotExist();
  }

  @Test
  void theHandInCarriesTheScenariosAndUnpacksThem(@TempDir Path tmp) throws Exception {
    Path dir = tmp.resolve("ws");
    try (Workspace ws = Workspace.open(dir, cell())) {
      ws.save(snapshot(ws, List.of(named("practice", World.empty()))));
    }
    Files.writeString(dir.resolve("scenarios/notes.txt"), "not a scenario");
    Path zip = tmp.resolve("h.zip");
    HandIn.Manifest m = HandIn.write(dir, zip, "Ada", "v", false);
    assertThat(m.files()).containsKey("scenarios/practice.json").doesNotContainKey("scenarios/notes.txt");
    try (ZipFile z = new ZipFile(zip.toFile())) {
      assertThat(z.stream().map(ZipEntry::getName)).contains("scenarios/practice.json");
    }
    Path back = tmp.resolve("back");
    HandIn.unpack(zip, back);
    try (Workspace ws = Workspace.open(back, cell(), true)) {
      assertThat(ws.otherScenarios()).extracting(Scenario::name).containsExactly("practice");
    }
  }
}
