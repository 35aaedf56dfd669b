package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.math.Xyzwpr;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.IoKind;
import org.robotrun.program.Position;
import org.robotrun.program.Program;
import org.robotrun.sim.Controller;

/** A workspace of a two-robot cell keeps every robot's state and programs, each robot its own. */
class CellWorkspaceTest {
  @Test
  void theSecondRobotsStateAndProgramsSurviveSaveAndOpen(@TempDir Path tmp) throws Exception {
    Path dir = WorkspaceFiles.createFromScenario(Path.of("scenarios/two-robot-handshake.json"), tmp.resolve("ws"));
    assertThat(dir.resolve("programs/LOADER.LS")).isRegularFile();
    assertThat(dir.resolve("programs/robot2/UNLOADER.LS")).isRegularFile();
    Program extra;
    try (WorkspaceSession s = WorkspaceSession.open(dir, false, Optional::empty, m -> {})) {
      assertThat(s.problems()).isEmpty();
      Controller one = s.sim.controllers().get(0);
      Controller two = s.sim.controllers().get(1);
      assertThat(one.programNames()).containsExactly("LOADER");
      assertThat(two.programNames()).containsExactly("UNLOADER");
      two.registers().setInteger(5, 42);
      two.registers().setString(3, "robot2 text");
      two.registers().setPosition(3, new Position.Joint(1, -2, 3, -4, 5, -6));
      two.registers().setBit(IoKind.DO, 7, true);
      two.setRegisterComment("R", 5, "parts out");
      two.setOverridePct(35);
      two.frames().setTransform(FrameKind.USER, 2, Xyzwpr.ofDegrees(300, 100, 50, 0, 0, 45).toTransform());
      two.frames().select(FrameKind.USER, 2);
      // A program of the same name on each robot: two different files.
      extra = two.program("UNLOADER").orElseThrow();
      one.saveProgram(renamed(extra, "SHARED"));
      two.saveProgram(renamed(extra, "SHARED"));
      two.deleteProgram("UNLOADER");
      one.registers().setInteger(5, 1);
      assertThat(s.autosave.saveNow(10_000)).isEmpty();
    }
    assertThat(dir.resolve("programs/SHARED.LS")).isRegularFile();
    assertThat(dir.resolve("programs/robot2/SHARED.LS")).isRegularFile();
    assertThat(dir.resolve("programs/robot2/UNLOADER.LS")).doesNotExist();
    try (WorkspaceSession s = WorkspaceSession.open(dir, false, Optional::empty, m -> {})) {
      assertThat(s.problems()).isEmpty();
      Controller one = s.sim.controllers().get(0);
      Controller two = s.sim.controllers().get(1);
      assertThat(one.programNames()).containsExactlyInAnyOrder("LOADER", "SHARED");
      assertThat(two.programNames()).containsExactly("SHARED");
      assertThat(two.registers().number(5)).isEqualTo(42);
      assertThat(one.registers().number(5)).isEqualTo(1);
      assertThat(two.registers().string(3)).isEqualTo("robot2 text");
      assertThat(one.registers().string(3)).as("SR[] are per controller").isEmpty();
      assertThat(two.registers().position(3)).isEqualTo(new Position.Joint(1, -2, 3, -4, 5, -6));
      assertThat(two.registers().bit(IoKind.DO, 7)).isTrue();
      assertThat(one.registers().bit(IoKind.DO, 7)).isFalse();
      assertThat(two.registerComment("R", 5)).isEqualTo("parts out");
      assertThat(two.overridePct()).isEqualTo(35);
      assertThat(two.frames().active(FrameKind.USER)).isEqualTo(2);
      Xyzwpr uf2 = Xyzwpr.fromTransform(two.frames().transform(FrameKind.USER, 2));
      assertThat(uf2.x()).isCloseTo(300, within(1e-6));
      assertThat(uf2.rDeg()).isCloseTo(45, within(1e-6));
      assertThat(one.frames().transform(FrameKind.USER, 2)).isEqualTo(org.robotrun.math.Transform.IDENTITY);
      // The wiring and each robot's main program are kept too.
      assertThat(s.workspace.scenario().wiring().wires()).hasSize(2);
      assertThat(s.workspace.scenario().robots().get(1).mainProgram()).contains("UNLOADER");
    }
    assertThat(Files.readString(dir.resolve("cell.json"))).contains("\"robots\" : {").contains("\"robot2\"");
  }

  @Test
  void aHandInOfATwoRobotCellCarriesEveryRobotsProgramsAndRunsBoth(@TempDir Path tmp) throws Exception {
    Path dir = WorkspaceFiles.createFromScenario(Path.of("scenarios/two-robot-handshake.json"), tmp.resolve("ws"));
    Path zip = tmp.resolve("hand-in.zip");
    org.robotrun.io.HandIn.Manifest m = org.robotrun.io.HandIn.write(dir, zip, "Ada", "test", false);
    assertThat(m.files()).containsKeys("cell.json", "programs/LOADER.LS", "programs/robot2/UNLOADER.LS");
    Path report = tmp.resolve("r.json");
    assertThat(Main.execute("run", "--workspace", zip.toString(), "--report", report.toString())).isZero();
    var r = new com.fasterxml.jackson.databind.ObjectMapper().readTree(report.toFile());
    assertThat(r.get("robots").get(1).get("program").asText()).isEqualTo("UNLOADER");
    assertThat(r.get("robots").get(1).get("status").asText()).isEqualTo("finished");
  }

  @Test
  void aLaterRobotsProgramEditedOutsideIsNoticedAndReloadedIntoThatRobot(@TempDir Path tmp) throws Exception {
    Path dir = WorkspaceFiles.createFromScenario(Path.of("scenarios/two-robot-handshake.json"), tmp.resolve("ws"));
    WindowCell cell = WindowCell.open(dir, new org.robotrun.io.UserDirs(tmp.resolve("data"), tmp.resolve("cfg")), m -> {},
        Optional::empty);
    try {
      Path file = dir.resolve("programs/robot2/UNLOADER.LS");
      String text = Files.readString(file);
      Files.writeString(file, text.replace("parts from the nest to the tray", "edited outside"));
      Files.setLastModifiedTime(file, java.nio.file.attribute.FileTime.fromMillis(System.currentTimeMillis() + 5000));
      var changes = cell.session.workspace.externalChanges();
      assertThat(changes).extracting(org.robotrun.io.Workspace.ExternalChange::programName).containsExactly("robot2/UNLOADER");
      cell.takeFile(file, new java.util.ArrayList<>());
      Controller two = cell.session.sim.controllers().get(1);
      assertThat(two.program("UNLOADER").orElseThrow().comment()).isEqualTo("edited outside");
      assertThat(cell.session.sim.controllers().get(0).program("UNLOADER")).isEmpty();
      assertThat(cell.session.workspace.externalChanges()).isEmpty();
    } finally {
      cell.close();
    }
  }

  private static Program renamed(Program p, String name) {
    String text = org.robotrun.io.LsWriter.write(p).replaceFirst("/PROG\\s+\\S+", "/PROG  " + name);
    return org.robotrun.io.LsReader.parse(name + ".LS", text).program();
  }
}
