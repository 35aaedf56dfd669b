package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.math.Transform;
import org.robotrun.robot.ForwardKinematics;
import org.robotrun.robot.IkSolver;
import org.robotrun.robot.RobotModel;

/**
 * The importer on URDFs as people write them beyond the tidy test packages: an arm with a
 * gripper (prismatic fingers, mimic joints, a hand that branches into fingers, a gripper after
 * tool0 or hung straight on link 6), and files with links without meshes, several visuals and
 * collisions per link, joints without {@code <origin>} or {@code <axis>}, continuous joints,
 * joints listed in odd order, ROS extras ({@code <transmission>}, {@code <gazebo>}), and xacro
 * leftovers.
 */
class UrdfVariedFilesTest {
  @TempDir
  Path tmp;

  private static final double[] Q = {0.3, -0.4, 0.5, 1.1, -0.7, 2.0};

  private RobotModel load(String name, String text) throws Exception {
    Path f = tmp.resolve(name);
    TestArms.write(f, text);
    return UrdfImporter.importRobot(f, Map.of()).model();
  }

  private UrdfImporter.Result result(String name, String text) throws Exception {
    Path f = tmp.resolve(name);
    TestArms.write(f, text);
    return UrdfImporter.importRobot(f, Map.of());
  }

  private static String arm(List<TestArms.J> joints) {
    return TestArms.urdf("arm", joints, l -> "    <collision><geometry><box size=\"0.05 0.05 0.05\"/></geometry></collision>\n");
  }

  /** The flange pose of the bare arm at Q, to compare with the arm plus whatever was added. */
  private Transform bareFlange() throws Exception {
    return ForwardKinematics.flangePoseInBase(load("bare.urdf", arm(TestArms.sphericalJoints())), Q);
  }

  private static List<TestArms.J> withGripper(String mount) {
    List<TestArms.J> j = new ArrayList<>(TestArms.sphericalJoints());
    j.add(TestArms.fixed("gripper_mount", mount, "gripper_base", TestArms.v(0, 0, 0.02), TestArms.v(0, 0, 0)));
    j.add(new TestArms.J("left_finger_joint", "prismatic", "gripper_base", "left_finger", TestArms.v(0, 0.01, 0.05),
        TestArms.v(0, 0, 0), TestArms.v(0, 1, 0), 0, 0.04, 0.2));
    j.add(new TestArms.J("right_finger_joint", "prismatic", "gripper_base", "right_finger", TestArms.v(0, -0.01, 0.05),
        TestArms.v(0, 0, 0), TestArms.v(0, -1, 0), 0, 0.04, 0.2));
    return j;
  }

  private static String mimic(String text, String joint, String of) {
    return text.replace("<joint name=\"" + joint + "\" type=\"prismatic\">",
        "<joint name=\"" + joint + "\" type=\"prismatic\">\n    <mimic joint=\"" + of + "\" multiplier=\"1\"/>");
  }

  @Test
  void aParallelGripperAfterTool0IsImportedFixedWithANote() throws Exception {
    String text = mimic(arm(withGripper("tool0")), "right_finger_joint", "left_finger_joint");
    UrdfImporter.Result r = result("gripper.urdf", text);
    assertThat(r.model().joints()).extracting(j -> j.name())
        .containsExactly("joint_1", "joint_2", "joint_3", "joint_4", "joint_5", "joint_6");
    assertThat(r.notes()).anyMatch(n -> n.startsWith("joint 'left_finger_joint' (prismatic, line ") && n.contains("imported as fixed at 0.0 mm"));
    assertThat(r.notes()).anyMatch(n -> n.startsWith("joint 'right_finger_joint' (prismatic, mimic, line "));
    // The arm is the same arm: same flange, same closed form.
    Transform f = ForwardKinematics.flangePoseInBase(r.model(), Q);
    assertThat(f.distanceTo(bareFlange())).isLessThan(1e-9);
    assertThat(IkSolver.forModel(r.model()).kind()).isEqualTo("closed-form");
    // The fingers' bodies ride on link 6.
    assertThat(r.model().links().get(6).shapes().size()).isGreaterThan(
        load("bare2.urdf", arm(TestArms.sphericalJoints())).links().get(6).shapes().size());
  }

  @Test
  void aHandHungOnLink6ThatBranchesIntoRevoluteFingersIsImported() throws Exception {
    List<TestArms.J> j = new ArrayList<>(TestArms.sphericalJoints());
    j.add(TestArms.fixed("hand_mount", "link_6", "hand", TestArms.v(0.02, 0, 0), TestArms.v(0, 0, 0)));
    j.add(TestArms.rev("finger_a", "hand", "fa", TestArms.v(0.03, 0.01, 0), TestArms.v(0, 0, 1), -0.5, 0.5, 1));
    j.add(TestArms.rev("finger_b", "hand", "fb", TestArms.v(0.03, -0.01, 0), TestArms.v(0, 0, 1), -0.5, 0.5, 1));
    j.add(TestArms.rev("finger_b_tip", "fb", "fb_tip", TestArms.v(0.03, 0, 0), TestArms.v(0, 0, 1), 0.1, 0.5, 1));
    UrdfImporter.Result r = result("hand.urdf", arm(j));
    assertThat(r.model().joints()).hasSize(6);
    assertThat(r.notes()).anyMatch(n -> n.startsWith("joint 'finger_b_tip' (revolute, line ") && n.contains("fixed at 5.7 deg"));
    assertThat(ForwardKinematics.flangePoseInBase(r.model(), Q).distanceTo(bareFlange())).isLessThan(1e-9);
  }

  @Test
  void aSeventhArmAxisIsStillRefusedEvenWithAHandAfterIt() throws Exception {
    List<TestArms.J> j = new ArrayList<>(TestArms.sphericalJoints());
    j.add(TestArms.rev("joint_7", "link_6", "link_7", TestArms.v(0.05, 0, 0), TestArms.v(1, 0, 0), -3, 3, 5));
    j.add(new TestArms.J("finger_l", "prismatic", "link_7", "fl", TestArms.v(0, 0.01, 0), TestArms.v(0, 0, 0), TestArms.v(0, 1, 0), 0, 0.04, 0.2));
    j.add(new TestArms.J("finger_r", "prismatic", "link_7", "fr", TestArms.v(0, -0.01, 0), TestArms.v(0, 0, 0), TestArms.v(0, -1, 0), 0, 0.04, 0.2));
    Path f = tmp.resolve("seven.urdf");
    String text = arm(j);
    TestArms.write(f, text);
    int line = text.substring(0, text.indexOf("<joint name=\"joint_7\"")).split("\n", -1).length;
    assertThatThrownBy(() -> UrdfImporter.importRobot(f, Map.of()))
        .hasMessageStartingWith(f + ":" + line + ": not a serial 6-axis arm: 9 moving joints")
        .hasMessageContaining("joint 'joint_7' continues the arm after the sixth");
  }

  @Test
  void aPrismaticJointInsideTheArmIsRefusedWithItsLine() throws Exception {
    List<TestArms.J> j = new ArrayList<>(TestArms.sphericalJoints());
    // A linear track under the arm: the first moving joint.
    j.add(0, new TestArms.J("track", "prismatic", "world", "base_link", TestArms.v(0, 0, 0), TestArms.v(0, 0, 0), TestArms.v(1, 0, 0), 0, 3, 1));
    Path f = tmp.resolve("track.urdf");
    String text = arm(j);
    TestArms.write(f, text);
    int line = text.substring(0, text.indexOf("<joint name=\"track\"")).split("\n", -1).length;
    assertThatThrownBy(() -> UrdfImporter.importRobot(f, Map.of()))
        .hasMessage(f + ":" + line + ": joint 'track' is prismatic: RobotRun's arms turn on six revolute joints; "
            + "a linear axis (track, gantry) is not supported");
  }

  @Test
  void oddButValidFilesImportToTheSameArm() throws Exception {
    Transform expected = bareFlange();
    String base = arm(TestArms.sphericalJoints());
    // Joints listed in reverse order, after a <transmission>, <gazebo> and comments.
    int firstJoint = base.indexOf("  <joint ");
    int end = base.indexOf("</robot>");
    String[] joints = base.substring(firstJoint, end).split("(?=  <joint )");
    StringBuilder reversed = new StringBuilder(base.substring(0, firstJoint));
    reversed.append("  <!-- a comment -->\n  <transmission name=\"t1\"><type>transmission_interface/SimpleTransmission</type>"
        + "<joint name=\"joint_1\"><hardwareInterface>EffortJointInterface</hardwareInterface></joint></transmission>\n"
        + "  <gazebo reference=\"link_1\"><material>Gazebo/Orange</material></gazebo>\n");
    for (int i = joints.length - 1; i >= 0; i--) {
      reversed.append(joints[i]);
    }
    reversed.append("</robot>\n");
    assertThat(ForwardKinematics.flangePoseInBase(load("reversed.urdf", reversed.toString()), Q).distanceTo(expected)).isLessThan(1e-9);
    // Links without any geometry, and one link with several visuals and collisions.
    String bare = TestArms.urdf("bare", TestArms.sphericalJoints(), l -> l.equals("link_2")
        ? "    <visual><geometry><box size=\"0.1 0.1 0.3\"/></geometry></visual>\n"
            + "    <visual><origin xyz=\"0 0 0.3\"/><geometry><sphere radius=\"0.05\"/></geometry></visual>\n"
            + "    <collision><geometry><box size=\"0.1 0.1 0.3\"/></geometry></collision>\n"
            + "    <collision><origin xyz=\"0 0 0.3\"/><geometry><cylinder radius=\"0.05\" length=\"0.1\"/></geometry></collision>\n"
        : "");
    RobotModel m = load("bare.urdf", bare);
    assertThat(m.links().get(2).shapes()).hasSize(2);
    assertThat(ForwardKinematics.flangePoseInBase(m, Q).distanceTo(expected)).isLessThan(1e-9);
    // No <origin> on fixed joints with a zero origin and no <axis> (default 1 0 0) on joint_4 and joint_6.
    String defaults = base.replace("<origin xyz=\"0.0 0.0 0.0\" rpy=\"0.0 0.0 0.0\"/>\n", "")
        .replace("<axis xyz=\"-1.0 0.0 0.0\"/>", "<axis xyz=\"-1 0 0\"/>");
    assertThat(defaults).doesNotContain("<origin xyz=\"0.0 0.0 0.0\" rpy=\"0.0 0.0 0.0\"/>");
    assertThat(ForwardKinematics.flangePoseInBase(load("defaults.urdf", defaults), Q).distanceTo(expected)).isLessThan(1e-9);
  }

  @Test
  void continuousJointsAndMissingLimitsAreHandledOrNamed() throws Exception {
    String base = arm(TestArms.sphericalJoints());
    // joint_6 is continuous in sphericalJoints; make joint_4 continuous with no <limit> at all.
    String cont = base.replace("<joint name=\"joint_4\" type=\"revolute\">", "<joint name=\"joint_4\" type=\"continuous\">")
        .replaceFirst("(<joint name=\"joint_4\" type=\"continuous\">[\\s\\S]*?)<limit [^>]*/>", "$1");
    UrdfImporter.Result r = result("cont.urdf", cont);
    assertThat(Math.toDegrees(r.model().joint(3).upperRad())).isCloseTo(360, org.assertj.core.data.Offset.offset(1e-9));
    assertThat(r.notes()).contains("joint 'joint_4' gives no velocity: assumed 180°/s");
    // velocity="0", as CAD exporters write it for "not set": assumed, with a note.
    UrdfImporter.Result zero = result("zero.urdf", base.replace("velocity=\"6.63\"", "velocity=\"0\""));
    assertThat(Math.toDegrees(zero.model().joint(1).maxSpeedRadPerSec())).isCloseTo(180, org.assertj.core.data.Offset.offset(1e-9));
    assertThat(zero.notes()).contains("joint 'joint_2' gives velocity 0 (not set): assumed 180°/s");
    // A revolute joint without <limit>: its line and what is expected.
    String noLimit = base.replaceFirst("(<joint name=\"joint_2\" type=\"revolute\">[\\s\\S]*?)<limit [^>]*/>", "$1");
    Path f = tmp.resolve("nolimit.urdf");
    TestArms.write(f, noLimit);
    int line = noLimit.substring(0, noLimit.indexOf("<joint name=\"joint_2\"")).split("\n", -1).length;
    assertThatThrownBy(() -> UrdfImporter.importRobot(f, Map.of())).hasMessage(f + ":" + line
        + ": joint 'joint_2': a revolute joint needs <limit lower=\"..\" upper=\"..\" velocity=\"..\"/> (radians, rad/s)");
  }

  @Test
  void xacroLeftoversAreNamedWithTheirLine() throws Exception {
    String base = arm(TestArms.sphericalJoints());
    String left = base.replace("<origin xyz=\"0.05 0.0 0.0\"", "<origin xyz=\"${a1} 0.0 0.0\"");
    Path f = tmp.resolve("left.urdf");
    TestArms.write(f, left);
    int line = left.substring(0, left.indexOf("${a1}")).split("\n", -1).length;
    assertThatThrownBy(() -> UrdfImporter.importRobot(f, Map.of()))
        .hasMessageStartingWith(f + ":" + line + ": ").hasMessageContaining("${a1}").hasMessageContaining("xacro");
    String macro = base.replace("<robot name=\"arm\">", "<robot name=\"arm\">\n  <xacro:include filename=\"$(find arm)/urdf/common.xacro\"/>");
    Path g = tmp.resolve("macro.urdf");
    TestArms.write(g, macro);
    assertThatThrownBy(() -> UrdfImporter.importRobot(g, Map.of())).hasMessageContaining("xacro")
        .hasMessageStartingWith(g + ":");
  }
}
