package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.math.Xyzwpr;
import org.robotrun.program.Config;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.IoKind;
import org.robotrun.program.Position;
import org.robotrun.program.Program;
import org.robotrun.sim.Controller;
import org.robotrun.sim.HeadlessRun;
import org.robotrun.world.CameraView;
import org.robotrun.world.WorldObject;

/** Every piece of a workspace's state survives save → open, headless. */
class WorkspaceRoundTripTest {
  private static final double MM = 1e-6;  // tolerance for lengths (mm) and angles (deg) written with 15 digits

  @Test
  void aWorkspaceMadeFromAScenarioKeepsItsModeSwitch(@TempDir Path tmp) throws Exception {
    // An AUTO exercise opened with --scenario must open in AUTO (the copy into the workspace dropped the mode).
    String text = Files.readString(Path.of("scenarios/pick-and-place.json"));
    assertThat(text).doesNotContain("\"mode\"");
    Path sc = tmp.resolve("auto.json");
    Files.writeString(sc, text.replaceFirst("\\{", "{\"mode\": \"AUTO\", ")
        .replace("\"programs/", "\"" + Path.of("scenarios").toAbsolutePath() + "/programs/"));
    Path dir = WorkspaceFiles.createFromScenario(sc, tmp.resolve("ws"));
    assertThat(Files.readString(dir.resolve("cell.json"))).containsPattern("\"mode\"\\s*:\\s*\"AUTO\"");
  }

  @Test
  void everyPieceOfStateSurvivesSaveAndOpen(@TempDir Path tmp) {
    Path dir = WorkspaceFiles.createFromScenario(Path.of("scenarios/pick-and-place.json"), tmp.resolve("ws"));
    CameraView view = new CameraView(new Vec3(100, -50, 200), 1800, Math.toRadians(30), Math.toRadians(25));
    Optional<CameraView> camera = Optional.of(view);
    WorldObject movedPart;
    Position.Joint jointsAfterRun;
    Program pickplace;
    try (WorkspaceSession s = WorkspaceSession.open(dir, false, () -> camera, m -> {})) {
      assertThat(s.problems()).isEmpty();
      Controller c = s.sim.controllers().get(0);
      // Run the exercise: the parts move onto the tray and the arm ends somewhere else than at the start.
      HeadlessRun.Result r = HeadlessRun.run(s.sim, c, "PICKPLACE", 120, sim -> {});
      assertThat(r.status()).isEqualTo(HeadlessRun.Status.FINISHED);
      movedPart = s.sim.world().find("part1").orElseThrow();
      assertThat(movedPart.pose()).isNotEqualTo(movedPart.startPose());
      jointsAfterRun = c.currentJoints();
      pickplace = c.program("PICKPLACE").orElseThrow();
      c.registers().setInteger(5, 42);
      c.registers().setReal(6, 3.0);
      c.registers().setReal(7, -1.25);
      c.registers().setString(2, "Part \"A\" ok");
      c.registers().setString(25, "x".repeat(254));
      c.registers().setPosition(3, new Position.Cartesian(10, 20, 30, 1, 2, 3, new Config(true, false, false, 1, 0, -1)));
      c.registers().setPosition(4, new Position.Joint(1, -2, 3, -4, 5, -6));
      c.registers().setBit(IoKind.DO, 7, true);
      c.registers().setValue(IoKind.GO, 2, 13);
      c.registers().setBit(IoKind.F, 9, true);
      c.setRegisterComment("R", 5, "count");
      c.setRegisterComment("PR", 3, "above tray");
      c.setOverridePct(35);
      c.frames().setTransform(FrameKind.USER, 4, Xyzwpr.ofDegrees(300, 100, 50, 0, 0, 45).toTransform());
      c.frames().setComment(FrameKind.USER, 4, "fixture B");
      c.frames().setTransform(FrameKind.TOOL, 3, Transform.translation(0, 10, 150));
      c.frames().select(FrameKind.TOOL, 3);
      c.frames().select(FrameKind.USER, 4);
      c.saveProgram(Program.of("EMPTY", java.util.List.of()));
      assertThat(s.autosave.saveNow(5000)).isEmpty();
    }
    assertThat(dir.resolve("programs/EMPTY.LS")).exists();

    try (WorkspaceSession s = WorkspaceSession.open(dir, false, Optional::empty, m -> {})) {
      assertThat(s.problems()).isEmpty();
      Controller c = s.sim.controllers().get(0);
      for (int j = 1; j <= 6; j++) {
        assertThat(c.currentJoints().element(j)).as("J%d", j).isCloseTo(jointsAfterRun.element(j), within(MM));
      }
      WorldObject part = s.sim.world().find("part1").orElseThrow();
      assertThat(part.parent()).isEqualTo(movedPart.parent());
      assertThat(Xyzwpr.fromTransform(part.pose()).position().minus(Xyzwpr.fromTransform(movedPart.pose()).position()).norm())
          .isLessThan(MM);
      assertThat(c.registers().number(5)).isEqualTo(42);
      assertThat(c.registers().isInteger(5)).isTrue();
      assertThat(c.registers().number(6)).isEqualTo(3.0);
      assertThat(c.registers().isInteger(6)).as("R[6] stays a real").isFalse();
      assertThat(c.registers().number(7)).isEqualTo(-1.25);
      assertThat(c.registers().string(2)).isEqualTo("Part \"A\" ok");
      assertThat(c.registers().string(25)).isEqualTo("x".repeat(254));
      assertThat(c.registers().string(1)).isEmpty();
      assertThat(c.registers().position(3)).isEqualTo(new Position.Cartesian(10, 20, 30, 1, 2, 3, new Config(true, false, false, 1, 0, -1)));
      assertThat(c.registers().position(4)).isEqualTo(new Position.Joint(1, -2, 3, -4, 5, -6));
      assertThat(c.registers().bit(IoKind.DO, 7)).isTrue();
      assertThat(c.registers().value(IoKind.GO, 2)).isEqualTo(13);
      assertThat(c.registers().bit(IoKind.F, 9)).isTrue();
      assertThat(c.registerComment("R", 5)).isEqualTo("count");
      assertThat(c.registerComment("PR", 3)).isEqualTo("above tray");
      assertThat(c.overridePct()).isEqualTo(35);
      assertThat(c.frames().active(FrameKind.TOOL)).isEqualTo(3);
      assertThat(c.frames().active(FrameKind.USER)).isEqualTo(4);
      assertThat(c.frames().comment(FrameKind.USER, 4)).isEqualTo("fixture B");
      assertThat(Xyzwpr.fromTransform(c.frames().transform(FrameKind.USER, 4)).rDeg()).isCloseTo(45, within(MM));
      assertThat(c.frames().transform(FrameKind.TOOL, 3).translationVector().z()).isCloseTo(150, within(MM));
      assertThat(c.programNames()).containsExactlyInAnyOrder("PICKPLACE", "EMPTY");
      assertThat(c.program("PICKPLACE").orElseThrow().lines()).isEqualTo(pickplace.lines());
      CameraView back = s.workspace.scenario().camera().orElseThrow();
      assertThat(back.distanceMm()).isCloseTo(1800, within(MM));
      assertThat(Math.toDegrees(back.yawRad())).isCloseTo(30, within(MM));
      assertThat(s.workspace.scenario().mainProgram()).contains("PICKPLACE");
    }
  }

  @Test
  void anUnchangedWorkspaceWritesNothing(@TempDir Path tmp) throws Exception {
    Path dir = WorkspaceFiles.createFromScenario(Path.of("scenarios/pick-and-place.json"), tmp.resolve("ws"));
    try (WorkspaceSession s = WorkspaceSession.open(dir, false, Optional::empty, m -> {})) {
      s.autosave.saveNow(5000);  // the first save writes cell.json in the workspace's own layout
    }
    var before = Files.getLastModifiedTime(dir.resolve("programs/PICKPLACE.LS"));
    var cellBefore = Files.readString(dir.resolve("cell.json"));
    Thread.sleep(20);
    try (WorkspaceSession s = WorkspaceSession.open(dir, false, Optional::empty, m -> {})) {
      assertThat(s.autosave.saveNow(5000)).isEmpty();
    }
    assertThat(Files.getLastModifiedTime(dir.resolve("programs/PICKPLACE.LS"))).isEqualTo(before);
    assertThat(Files.readString(dir.resolve("cell.json"))).isEqualTo(cellBefore);
  }
}
