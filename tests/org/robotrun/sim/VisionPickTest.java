package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.world.Scenario;
import org.robotrun.world.World;

/**
 * The vision lab (scenarios/vision-pick.json, VISPICK.LS): four blocks dropped at random, found by
 * a fixed camera and placed on the tray with VOFFSET, for seeds 1..50 (about 0.1 s of wall time
 * each); {@code VisionPickFuzzCampaign} (-Pfuzz) runs a thousand more.
 */
class VisionPickTest {
  static final Scenario LAB = CellRig.scenario("vision-pick.json");

  static Simulation cell(long seed) {
    return CellRig.cell(LAB.withVision(LAB.vision().withSeed(seed)));
  }

  // Left out of the mutation run (-Pmutation, docs/testing.md): fifty whole lab runs for each
  // mutant it covers; the other two tests here run the same program.
  @Tag("mutation-slow")
  @Test
  void exampleProgramPlacesEveryBlockOnTheTrayForFiftySeeds() {
    assertThat(failures(1, 50)).isEmpty();
  }

  /** What went wrong for each seed in from..to: a run that did not finish, a block not on the tray, a collision. */
  static List<String> failures(long from, long to) {
    List<String> failures = new ArrayList<>();
    for (long seed = from; seed <= to; seed++) {
      Simulation sim = cell(seed);
      HeadlessRun.Result r = HeadlessRun.run(sim, sim.controllers().get(0), "VISPICK", 120, s -> {});
      World w = sim.world();
      List<String> off = new ArrayList<>();
      for (int k = 1; k <= 4; k++) {
        String part = "block" + k;
        // On the tray and inside its 180 x 180 mm top (tray centre at cell (400, 180)).
        Vec3 p = w.poseInCell(part).translationVector();
        boolean onTray = w.find(part).orElseThrow().parent().equals(java.util.Optional.of("tray"))
            && Math.abs(p.x() - 400) <= 70 && Math.abs(p.y() - 180) <= 70;
        if (!onTray) {
          off.add(part);
        }
      }
      if (r.status() != HeadlessRun.Status.FINISHED || !off.isEmpty() || !sim.collisionEvents().isEmpty()) {
        failures.add("seed " + seed + ": " + r.status() + " " + r.alarm().map(Object::toString).orElse("")
            + " not on the tray: " + off + " collisions: " + sim.collisionEvents());
      }
    }
    return failures;
  }

  @Test
  void differentSeedsPlaceTheBlocksDifferentlyAndTheSameSeedAlike() {
    World a = cell(7).world();
    World b = cell(7).world();
    World c = cell(8).world();
    for (int k = 1; k <= 4; k++) {
      String part = "block" + k;
      assertThat(a.poseInCell(part)).isEqualTo(b.poseInCell(part));
      assertThat(a.poseInCell(part).distanceTo(c.poseInCell(part))).as(part).isGreaterThan(1.0);
    }
  }

  @Test
  void placedBlocksStayInTheirRangesAndApart() {
    for (long seed = 1; seed <= 200; seed++) {
      World w = cell(seed).world();
      List<Vec3> at = new ArrayList<>();
      for (int k = 1; k <= 4; k++) {
        Transform X_CP = w.poseInCell("block" + k);
        // Table frame: x -150..50, y -310..-60 (table origin at cell (420, 0)); on the table top.
        assertThat(X_CP.x() - 420).isBetween(-150.0, 50.0);
        assertThat(X_CP.y()).isBetween(-310.0, -60.0);
        assertThat(X_CP.z()).isEqualTo(-100.0, org.assertj.core.data.Offset.offset(1e-9));
        for (Vec3 o : at) {
          assertThat(Math.hypot(o.x() - X_CP.x(), o.y() - X_CP.y())).as("seed " + seed).isGreaterThanOrEqualTo(90.0);
        }
        at.add(X_CP.translationVector());
      }
    }
  }
}
