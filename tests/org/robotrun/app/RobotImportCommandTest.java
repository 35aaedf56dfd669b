package org.robotrun.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.io.TestArms;
import org.robotrun.render.GlTestSupport;

/** {@code robotrun robot import}: writes a robot folder a scenario can name, or refuses in one line. */
class RobotImportCommandTest {
  @TempDir Path tmp;

  @Test
  void importsTheArmAndPrintsItsBodiesAgainstTheirHulls() throws Exception {
    Path urdf = TestArms.sphericalPackage(tmp);
    Path out = tmp.resolve("robots/arm");
    RenderCommandTest.Run r = RenderCommandTest.run("robot", "import", urdf.toString(),
        "--package", "extra=" + TestArms.extraPackage(tmp).get("extra"), "--out", out.toString());
    assertThat(r.exitCode()).as(r.err()).isZero();
    assertThat(r.out()).contains("robot 'test_arm' (id test_arm): 6 joints")
        .containsPattern("link_3 +fitted to collision mesh package://arm_support/meshes/visual/link_3.dae +1320.0 +1320.0 +1.00")
        .contains("note: flange: link 'tool0'")
        .contains("wrote " + out.toAbsolutePath().resolve("test_arm.json"));
    assertThat(out.resolve("test_arm.json")).isRegularFile();
    try (Stream<Path> s = Files.list(out.resolve("meshes"))) {
      assertThat(s.count()).isEqualTo(8);
    }
  }

  @Test
  void aRefusedImportIsOneLineWithExitCode2AndLeavesNothing() throws Exception {
    Path urdf = TestArms.sphericalPackage(tmp);
    Path out = tmp.resolve("robots/arm");
    // Without --package the 'extra' package cannot be found.
    RenderCommandTest.Run r = RenderCommandTest.run("robot", "import", urdf.toString(), "--out", out.toString());
    assertThat(r.exitCode()).isEqualTo(2);
    assertThat(r.err().strip().lines()).hasSize(1);
    assertThat(r.err()).startsWith("robotrun: " + urdf + ":").contains("package 'extra' not found").doesNotContain("\tat ");
    assertThat(out).doesNotExist();
    assertThat(tmp.resolve("robots")).satisfiesAnyOf(d -> assertThat(d).doesNotExist(), d -> assertThat(d).isEmptyDirectory());
  }

  @Test
  void benchImportPrintsColdAndWarmTimes() throws Exception {
    RenderCommandTest.Run r = RenderCommandTest.run("bench", "import", TestArms.offsetPackage(tmp).toString(), "--rounds", "2");
    assertThat(r.exitCode()).as(r.err()).isZero();
    assertThat(r.out()).matches("robot=ur_like triangles=904 fitted_boxes=6 cold_import_ms=[0-9.]+ cold_import_cpu_ms=[0-9.]+ "
        + "import_ms=[0-9.]+ import_cpu_ms=[0-9.]+ write_ms=[0-9.]+ rounds=2\\R");
    try (Stream<Path> s = Files.list(tmp)) {
      assertThat(s.map(p -> p.getFileName().toString())).containsExactly("ur");
    }
  }

  @Test
  void aScenarioWithTheImportedArmRenders() throws Exception {
    GlTestSupport.rendererOrSkip(16, 16).close();
    Path out = tmp.resolve("robots/ur");
    RenderCommandTest.Run imp = RenderCommandTest.run("robot", "import", TestArms.offsetPackage(tmp).toString(), "--out", out.toString());
    assertThat(imp.exitCode()).as(imp.err()).isZero();
    Path cell = tmp.resolve("cell.json");
    Files.writeString(cell, """
        {"format": 1, "robots": [{"name": "robot1", "model": "robots/ur/ur_like.json", "basePose": {"x": 0, "y": 0, "z": -89.159}, "jointsDeg": [0, -60, 60, 0, 90, 0]}]}
        """);
    Path png = tmp.resolve("ur.png");
    RenderCommandTest.Run r = RenderCommandTest.run("render", "--scenario", cell.toString(), "--out", png.toString(),
        "--width", "320", "--height", "200");
    assertThat(r.exitCode()).as(r.err()).isZero();
    assertThat(javax.imageio.ImageIO.read(png.toFile()).getWidth()).isEqualTo(320);
  }
}
