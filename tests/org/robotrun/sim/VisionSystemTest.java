package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.math.Xyzwpr;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.world.Scenario;
import org.robotrun.world.VisionSetup;

/**
 * RUN_FIND against the vision lab's cell: what is found, where, with which noise. Poses compared in
 * UF[1] (the process's frame); tolerances say their units.
 */
class VisionSystemTest {
  static final Scenario LAB = VisionPickTest.LAB;

  static VisionSetup withCamera(VisionSetup v, VisionSetup.Camera c) {
    return new VisionSetup(v.seed(), List.of(c), v.models(), v.processes(), v.placements());
  }

  static VisionSetup.Camera camera(VisionSetup v, double noiseMm, double noiseDeg, double miss) {
    VisionSetup.Camera c = v.cameras().get(0);
    return new VisionSetup.Camera(c.name(), c.robot(), c.pose(), c.fovRad(), c.widthPx(), c.heightPx(), c.window(),
        noiseMm, Math.toRadians(noiseDeg), miss);
  }

  static Simulation cell(VisionSetup v) {
    return CellRig.cell(LAB.withVision(v));
  }

  static List<VisionSystem.Detection> find(Simulation sim) {
    VisionSystem vs = sim.vision().orElseThrow();
    return vs.find(sim.controllers().get(0), vs.setup().process("find_blocks").orElseThrow());
  }

  /** The part's true pose in UF[1]. */
  static Xyzwpr truePose(Simulation sim, String part) {
    Transform X_WU = sim.controllers().get(0).frames().transform(FrameKind.USER, 1);
    Transform X_CU = sim.robotPlacements().get(0).compose(X_WU);
    return Xyzwpr.fromTransform(X_CU.inverse().compose(sim.world().poseInCell(part)));
  }

  @Test
  void withoutNoiseTheFoundPosesAreTheTruePosesAndTheOffsetMapsTheReferenceOntoThem() {
    VisionSetup v = withCamera(LAB.vision(), camera(LAB.vision(), 0, 0, 0));
    for (long seed = 1; seed <= 20; seed++) {
      Simulation sim = cell(v.withSeed(seed));
      List<VisionSystem.Detection> found = find(sim);
      assertThat(found).extracting(VisionSystem.Detection::part)
          .containsExactlyInAnyOrder("block1", "block2", "block3", "block4");
      for (VisionSystem.Detection d : found) {
        Xyzwpr t = truePose(sim, d.part());
        Xyzwpr f = d.result().found().toXyzwpr();
        assertThat(f.x()).isCloseTo(t.x(), offset(1e-9));
        assertThat(f.y()).isCloseTo(t.y(), offset(1e-9));
        assertThat(f.z()).isCloseTo(t.z(), offset(1e-9));
        assertThat(Math.IEEEremainder(f.rDeg() - t.rDeg(), 360)).isCloseTo(0, offset(1e-9));
        // found = OFFSET · reference (the fixed frame offset), to 1e-9 mm
        Transform ref = v.processes().get(0).reference();
        Transform back = d.result().offset().toXyzwpr().toTransform().compose(ref);
        assertThat(back.distanceTo(d.result().found().toXyzwpr().toTransform())).isLessThan(1e-9);
        // a 2D offset: X, Y and R only
        Xyzwpr o = d.result().offset().toXyzwpr();
        assertThat(o.z()).isCloseTo(0, offset(1e-9));
        assertThat(o.w()).isCloseTo(0, offset(1e-12));
        assertThat(o.p()).isCloseTo(0, offset(1e-12));
        assertThat(d.result().modelId()).isEqualTo(1);
        assertThat(d.result().userFrame()).isEqualTo(1);
      }
    }
  }

  @Test
  void foundPositionsScatterAroundTheTruePosesWithTheConfiguredNoise() {
    double sigmaMm = 0.5;
    double sigmaDeg = 0.4;
    Simulation sim = cell(withCamera(LAB.vision(), camera(LAB.vision(), sigmaMm, sigmaDeg, 0)));
    double sum = 0;
    double sumSq = 0;
    double sumR = 0;
    double sumRSq = 0;
    int n = 0;
    for (int run = 0; run < 300; run++) {
      for (VisionSystem.Detection d : find(sim)) {
        Xyzwpr t = truePose(sim, d.part());
        Xyzwpr f = d.result().found().toXyzwpr();
        double ex = f.x() - t.x();
        double er = Math.IEEEremainder(f.rDeg() - t.rDeg(), 360);
        // within 6 sigma, every one
        assertThat(Math.abs(ex)).isLessThan(6 * sigmaMm);
        assertThat(Math.abs(f.y() - t.y())).isLessThan(6 * sigmaMm);
        assertThat(Math.abs(er)).isLessThan(6 * sigmaDeg);
        sum += ex;
        sumSq += ex * ex;
        sumR += er;
        sumRSq += er * er;
        n++;
      }
    }
    assertThat(n).isEqualTo(1200);
    // 1200 samples: the sample mean is within 4 standard errors of 0, the deviation within 10 %
    assertThat(Math.abs(sum / n)).isLessThan(4 * sigmaMm / Math.sqrt(n));
    assertThat(Math.sqrt(sumSq / n)).isCloseTo(sigmaMm, offset(0.1 * sigmaMm));
    assertThat(Math.abs(sumR / n)).isLessThan(4 * sigmaDeg / Math.sqrt(n));
    assertThat(Math.sqrt(sumRSq / n)).isCloseTo(sigmaDeg, offset(0.1 * sigmaDeg));
  }

  @Test
  void theSameSeedGivesTheSameResultsAndAnotherSeedOthers() {
    List<VisionSystem.Detection> a = find(VisionPickTest.cell(3));
    List<VisionSystem.Detection> b = find(VisionPickTest.cell(3));
    List<VisionSystem.Detection> c = find(VisionPickTest.cell(4));
    assertThat(a).isEqualTo(b);
    assertThat(a).isNotEqualTo(c);
  }

  @Test
  void resultsComeBestScoreFirstAndNumberToFindCapsThem() {
    VisionSetup v = LAB.vision();
    VisionSetup.Process p = v.processes().get(0);
    VisionSetup two = new VisionSetup(v.seed(), v.cameras(), v.models(), List.of(new VisionSetup.Process(p.name(),
        p.camera(), p.models(), p.userFrame(), p.reference(), p.type(), 2)), v.placements());
    Simulation all = cell(v);
    List<VisionSystem.Detection> found = find(all);
    for (int i = 1; i < found.size(); i++) {
      assertThat(found.get(i).result().score()).isLessThanOrEqualTo(found.get(i - 1).result().score());
    }
    assertThat(find(cell(two))).hasSize(2);
  }

  @Test
  void aMissProbabilityOfOneFindsNothingAndASearchWindowOutsideThePartsFindsNothing() {
    assertThat(find(cell(withCamera(LAB.vision(), camera(LAB.vision(), 0, 0, 1))))).isEmpty();
    VisionSetup.Camera c = LAB.vision().cameras().get(0);
    // The blocks lie in the lower-left of the image (u < 320); a window on the right half misses them all.
    VisionSetup.Camera right = new VisionSetup.Camera(c.name(), c.robot(), c.pose(), c.fovRad(), c.widthPx(),
        c.heightPx(), new VisionSetup.Window(600, 0, 640, 20), 0, 0, 0);
    assertThat(find(cell(withCamera(LAB.vision(), right)))).isEmpty();
  }

  @Test
  void aThreeDProcessReportsTheFullPose() {
    VisionSetup v = withCamera(LAB.vision(), camera(LAB.vision(), 0, 0, 0));
    VisionSetup.Process p = v.processes().get(0);
    Transform tilted = Xyzwpr.ofDegrees(120, 170, 5, 3, -2, 10).toTransform();
    VisionSetup three = new VisionSetup(v.seed(), v.cameras(), v.models(), List.of(new VisionSetup.Process(p.name(),
        p.camera(), p.models(), p.userFrame(), tilted, VisionSetup.ProcessType.THREE_D, 10)), v.placements());
    Simulation sim = cell(three);
    for (VisionSystem.Detection d : find(sim)) {
      Transform X_UT = truePose(sim, d.part()).toTransform();
      assertThat(d.result().found().toXyzwpr().toTransform().distanceTo(X_UT)).isLessThan(1e-9);
      assertThat(d.result().offset().toXyzwpr().toTransform().compose(tilted).distanceTo(X_UT)).isLessThan(1e-6);
    }
  }

  @Test
  void aRobotMountedCameraFollowsTheFlange() {
    VisionSetup v = LAB.vision();
    // Looking along the flange's z axis (the tool points down at HOME), wide angle.
    VisionSetup.Camera onTool = new VisionSetup.Camera("CAM1", Optional.of("robot1"), Transform.IDENTITY,
        Math.toRadians(150), 640, 480, new VisionSetup.Window(0, 0, 640, 480), 0, 0, 0);
    Simulation sim = cell(withCamera(v, onTool));
    VisionSystem vs = sim.vision().orElseThrow();
    Controller c = sim.controllers().get(0);
    Transform X_CF = sim.robotPlacements().get(0).compose(
        org.robotrun.robot.ForwardKinematics.flangePoseInWorld(c.model(), c.jointsRad()));
    assertThat(vs.cameraPose(onTool).distanceTo(X_CF)).isLessThan(1e-9);
    List<VisionSystem.Detection> found = find(sim);
    assertThat(found).isNotEmpty();
    for (VisionSystem.Detection d : found) {
      Xyzwpr t = truePose(sim, d.part());
      assertThat(d.result().found().xMm()).isCloseTo(t.x(), offset(1e-9));
      assertThat(d.result().found().yMm()).isCloseTo(t.y(), offset(1e-9));
    }
  }

  @Test
  void reseedPlacesThePartsAnewClearsTheRegistersAndResetSceneKeepsTheNewPlaces() {
    Simulation sim = VisionPickTest.cell(5);
    Controller c = sim.controllers().get(0);
    c.registers().vision().set(1, find(sim).get(0).result());
    Transform before = sim.world().poseInCell("block1");
    VisionSystem v = VisionSystem.reseed(sim, sim.vision().orElseThrow().setup(), 6);
    assertThat(v.setup().seed()).isEqualTo(6);
    assertThat(sim.vision()).containsSame(v);
    assertThat(c.registers().vision().get(1)).isEmpty();
    Transform after = sim.world().poseInCell("block1");
    assertThat(after.distanceTo(before)).isGreaterThan(1.0);
    // the same places as a cell built with seed 6
    assertThat(after).isEqualTo(VisionPickTest.cell(6).world().poseInCell("block1"));
    sim.resetScene();
    assertThat(sim.world().poseInCell("block1")).isEqualTo(after);
  }
}
