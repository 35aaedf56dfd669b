package org.robotrun.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Arrays;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.robotrun.collision.Body;
import org.robotrun.collision.CollisionWorld;
import org.robotrun.collision.Contact;
import org.robotrun.collision.StandardPairFilter;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Transform;
import org.robotrun.robot.ForwardKinematics;
import org.robotrun.robot.JointConvention;
import org.robotrun.robot.RobotModel;
import org.robotrun.world.EndEffectorGeometry;
import org.robotrun.world.EndEffectorType;
import org.robotrun.world.RobotBodies;

/** Self-collision of one LR Mate with the example gripper under the simulation's rules. */
class CellPairFilterTest {
  final RobotModel model = RobotDefinitions.defaultRobot();
  final CollisionWorld world = new CollisionWorld(new CellPairFilter(StandardPairFilter.nothingHeld()));
  final RobotBodies robot;

  CellPairFilterTest() {
    var boxes = CellCollisions.boxes(model, Transform.IDENTITY);
    boxes.set(Body.TOOL_LINK, EndEffectorGeometry.of(EndEffectorType.GRIPPER).boxes(EndEffectorGeometry.FINGER_OPEN_GAP_MM));
    robot = new RobotBodies("r", boxes, world);
  }

  /** Self contacts at pendant joints {@code deg}. */
  List<Contact> contactsAt(double... deg) {
    double[] q = JointConvention.pendantToKinematic(model, Arrays.stream(deg).map(Math::toRadians).toArray());
    assertThat(model.firstJointOutsideLimits(q)).as("legal pose").isEqualTo(-1);
    Transform[] X_WL = ForwardKinematics.linkPosesInWorld(model, q);
    Transform[] all = Arrays.copyOf(X_WL, Body.TOOL_LINK + 1);
    all[Body.TOOL_LINK] = X_WL[RobotModel.DOF].compose(model.X_6F());
    robot.moveTo(all, world);
    world.update();
    return world.contacts();
  }

  // Left out of the mutation run (-Pmutation, docs/testing.md): 20 000 poses through every
  // collision class for each mutant it covers; the pair rules and overlap tests are killed by
  // the truth tables and the overlap oracles.
  @Tag("mutation-slow")
  @Test
  void armNeverTouchesItselfAnywhereInTheWorkEnvelope() {
    // 20 000 seeded poses: J1, J4, J6 over their whole range, J2 -30..60, J3 -30..60 (pendant),
    // J5 -90..90 (the tool not folded back onto the forearm), with the wrist centre at least
    // 250 mm out from the J1 axis (working in front of the arm: a 120 mm gripper on a wrist
    // nearer than that can reach back into the shoulder, a real collision).
    Random rnd = new Random(6);
    double[] lo = {-170, -30, -30, -190, -90, -360};
    double[] hi = {170, 60, 60, 190, 90, 360};
    int checked = 0;
    for (int s = 0; s < 20_000; s++) {
      double[] deg = new double[6];
      for (int j = 0; j < 6; j++) {
        deg[j] = lo[j] + rnd.nextDouble() * (hi[j] - lo[j]);
      }
      double[] q = JointConvention.pendantToKinematic(model, Arrays.stream(deg).map(Math::toRadians).toArray());
      if (model.firstJointOutsideLimits(q) >= 0) {
        continue;
      }
      Transform X_W5 = ForwardKinematics.linkPosesInWorld(model, q)[5];
      if (Math.hypot(X_W5.x(), X_W5.y()) < 250) {
        continue;
      }
      assertThat(contactsAt(deg)).as(Arrays.toString(deg)).isEmpty();
      checked++;
    }
    assertThat(checked).isGreaterThan(10_000);
  }

  @Test
  void linksTwoApartOverlapByConstructionAndAreNotChecked() {
    // At HOME link 2's elbow housing and link 4's forearm boxes overlap: a checked pair would
    // alarm in every pose.
    assertThat(contactsAt(0, 0, 0, 0, -90, 0)).isEmpty();
    int elbow = -1;
    int forearm = -1;
    for (int h = 0; h < world.size(); h++) {
      String n = world.body(h).name();
      elbow = n.equals("r/link2#2") ? h : elbow;
      forearm = n.equals("r/link4#1") ? h : forearm;
    }
    assertThat(world.box(elbow).overlaps(world.box(forearm))).isTrue();
    assertThat(new CellPairFilter(StandardPairFilter.nothingHeld()).mayCollide(world.body(elbow), world.body(forearm))).isFalse();
  }

  @Test
  void wristFoldedDownIntoTheBaseIsCaught() {
    List<Contact> c = contactsAt(0, 110, -160, 0, 90, 0);
    assertThat(c).isNotEmpty();
    assertThat(c).anySatisfy(k -> {
      assertThat(k.a().link()).isZero();
      assertThat(k.b().link()).isGreaterThanOrEqualTo(4);
    });
  }

  @Test
  void gripperFoldedBackOntoTheForearmIsCaught() {
    List<Contact> c = contactsAt(66, 88, 31, 162, -124, 248);
    assertThat(c).extracting(k -> k.a().name() + "|" + k.b().name()).contains("r/link4#1|r/tool#1");
  }

  @Test
  void aTouchableObjectMayBeTouchedByTheToolButNotByTheArm() {
    var f = new CellPairFilter(StandardPairFilter.nothingHeld(), java.util.Set.of("marker"));
    Body tool = Body.robotLink("r", Body.TOOL_LINK, "r/tool/tip");
    Body link5 = Body.robotLink("r", 5, "r/link5");
    Body marker = Body.fixture("marker", "marker");
    Body jig = Body.fixture("jig", "jig");
    assertThat(f.mayCollide(tool, marker)).isFalse();
    assertThat(f.mayCollide(marker, tool)).isFalse();
    assertThat(f.mayCollide(link5, marker)).isTrue();
    assertThat(f.mayCollide(tool, jig)).isTrue();
    assertThat(new CellPairFilter(StandardPairFilter.nothingHeld()).mayCollide(tool, marker)).isTrue();
  }
}
