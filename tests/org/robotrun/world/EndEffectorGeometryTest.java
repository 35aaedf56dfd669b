package org.robotrun.world;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.robotrun.collision.Obb;
import org.robotrun.math.Transform;

/** The standard tools: TCP, boxes short of the TCP where a tool touches things, pickup zones. */
class EndEffectorGeometryTest {

  /** Highest z (flange frame) any collision box of {@code g} reaches with the fingers open. */
  static double reach(EndEffectorGeometry g) {
    double top = 0;
    for (LocalBox b : g.boxes(EndEffectorGeometry.FINGER_OPEN_GAP_MM)) {
      Obb o = b.inWorld(Transform.IDENTITY);
      top = Math.max(top, o.cz() + o.hz());
    }
    return top;
  }

  @Test
  void everyTypeHasBoxesNamedOneToOneAndNoneTouchesTheFlange() {
    for (EndEffectorType t : EndEffectorType.values()) {
      EndEffectorGeometry g = EndEffectorGeometry.of(t);
      assertThat(g.boxNames()).as(t.fileName()).hasSameSizeAs(g.boxes(10));
      for (LocalBox b : g.boxes(EndEffectorGeometry.FINGER_OPEN_GAP_MM)) {
        Obb o = b.inWorld(Transform.IDENTITY);
        assertThat(o.cz() - o.hz()).as(t.fileName() + " box bottom (mm)").isGreaterThanOrEqualTo(EndEffectorGeometry.FLANGE_GAP_MM - 1e-9);
      }
    }
    assertThat(EndEffectorGeometry.of(EndEffectorType.FACEPLATE).boxes(0)).isEmpty();
    assertThat(EndEffectorGeometry.of(EndEffectorType.FACEPLATE).X_FT()).isEqualTo(Transform.IDENTITY);
  }

  @Test
  void gripperFingersEndAtTheTcpOthersStopShortOfIt() {
    assertThat(reach(EndEffectorGeometry.of(EndEffectorType.GRIPPER))).isEqualTo(120.0);
    assertThat(reach(EndEffectorGeometry.of(EndEffectorType.SUCTION))).isEqualTo(109.0);
    assertThat(reach(EndEffectorGeometry.of(EndEffectorType.POINTER))).isEqualTo(148.0);
    assertThat(reach(EndEffectorGeometry.of(EndEffectorType.GLUEGUN))).isEqualTo(138.0);
  }

  @Test
  void onlyGripperAndSuctionPickAndTheirZoneReachesTheTcp() {
    for (EndEffectorType t : EndEffectorType.values()) {
      EndEffectorGeometry g = EndEffectorGeometry.of(t);
      boolean picks = t == EndEffectorType.GRIPPER || t == EndEffectorType.SUCTION;
      assertThat(g.picksParts()).as(t.fileName()).isEqualTo(picks);
      g.pickupZone().ifPresent(z -> {
        Obb o = z.inWorld(Transform.IDENTITY);
        assertThat(o.cz() + o.hz()).as(t.fileName() + " zone end").isGreaterThanOrEqualTo(g.X_FT().z());
      });
    }
    assertThat(EndEffectorGeometry.of(EndEffectorType.GLUEGUN).leavesTrace()).isTrue();
  }

  @Test
  void fingersCloseSymmetricallyAboutTheToolAxis() {
    var f = EndEffectorGeometry.of(EndEffectorType.GRIPPER).fingerBoxes(40);
    assertThat(f).hasSize(2);
    double y1 = f.get(0).X_LB().y();
    double y2 = f.get(1).X_LB().y();
    assertThat(y1).isEqualTo(-y2);
    // Inner faces 40 mm apart.
    assertThat(Math.abs(y2 - y1) - 2 * f.get(0).hyMm()).isEqualTo(40.0);
  }
}
