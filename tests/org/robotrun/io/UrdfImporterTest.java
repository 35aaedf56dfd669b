package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.robotrun.math.Transform;
import org.robotrun.robot.ForwardKinematics;
import org.robotrun.robot.LinkMesh;
import org.robotrun.robot.LinkShape;
import org.robotrun.robot.LinkSpec;
import org.robotrun.robot.RobotModel;

/** URDF packages written here are imported as real ones ship: meshes, packages, frames, faults. */
class UrdfImporterTest {
  @TempDir Path tmp;

  private Path sphericalArm() throws Exception {
    return TestArms.sphericalPackage(tmp);
  }

  private Map<String, Path> extraPackage() {
    return TestArms.extraPackage(tmp);
  }

  // Method: every link pose and the flange (tool0) from the importer against TestArms.pose, an
  // FK of the URDF numbers written in the test, at zero and 200 random joint vectors (seed 24).
  // Tolerance 1e-6 mm and 1e-9 rad.
  @Test
  void sphericalWristArmHasTheUrdfsForwardKinematics() throws Exception {
    UrdfImporter.Result r = UrdfImporter.importRobot(sphericalArm(), extraPackage());
    assertSameFk(r.model(), TestArms.sphericalJoints(), "tool0");
    assertThat(r.model().links().stream().map(LinkSpec::name))
        .containsExactly("base_link", "link_1", "link_2", "link_3", "link_4", "link_5", "link_6");
  }

  @Test
  void offsetWristArmHasTheUrdfsForwardKinematics() throws Exception {
    Path file = TestArms.offsetPackage(tmp);
    UrdfImporter.Result r = UrdfImporter.importRobot(file, Map.of());
    assertSameFk(r.model(), TestArms.offsetJoints(), "tool0");
    assertThat(r.model().joints().get(0).name()).isEqualTo("shoulder_pan_joint");
    assertThat(r.model().links().get(0).shapes()).singleElement().isInstanceOf(LinkShape.Cylinder.class);
    assertThat(r.model().links().get(1).shapes()).singleElement().isInstanceOf(LinkShape.Box.class);
    assertThat(r.model().links().get(1).meshes()).singleElement().extracting(LinkMesh::color).isEqualTo("#598ccc");
    for (UrdfImporter.BodyReport b : r.bodies()) {
      System.out.printf(java.util.Locale.ROOT, "offset arm body %-15s %-50s box %10.1f cm3 hull %10.1f cm3 ratio %.3f%n",
          b.link(), b.source(), b.boxVolumeMm3() / 1000, b.hullVolumeMm3() / 1000, b.ratio());
      if (!Double.isNaN(b.hullVolumeMm3())) {
        assertThat(b.ratio()).as(b.link()).isBetween(1.0, 1.6);
      }
    }
  }

  // A layout as ROS-Industrial ships it: a "world" root, <axis> left out (URDF's default x),
  // an upper-case .STL, comments, and only a "flange" link after joint 6.
  @Test
  void rosIndustrialLayoutWithDefaultsImports() throws Exception {
    Path pkg = tmp.resolve("ws/src/m_support");
    TestArms.packageXml(pkg, "m_support");
    MeshFiles.stlBinary(pkg.resolve("meshes/BASE_LINK.STL"), MeshFiles.box(TestArms.v(-0.1, -0.1, 0), TestArms.v(0.1, 0.1, 0.2)));
    List<TestArms.J> joints = new ArrayList<>();
    joints.add(TestArms.fixed("world-base_link", "world", "base_link", TestArms.v(0, 0, 0), TestArms.v(0, 0, 0)));
    String parent = "base_link";
    double[][] xyz = {{0, 0, 0.45}, {0.15, 0, 0}, {0, 0, 0.6}, {0, 0, 0.2}, {0.64, 0, 0}, {0.1, 0, 0}};
    for (int i = 0; i < 6; i++) {
      double[] axis = i % 3 == 0 ? TestArms.v(0, 0, 1) : TestArms.v(1, 0, 0);
      joints.add(TestArms.rev("joint_" + (i + 1), parent, "link_" + (i + 1), xyz[i], axis, -3, 3, 4));
      parent = "link_" + (i + 1);
      if (i == 2) {
        // A turned adapter between two moving joints: joint_4 hangs from a merged link.
        joints.add(TestArms.fixed("adapter", parent, "link_3_adapter", TestArms.v(0.01, 0.02, 0.03), TestArms.v(0.3, -0.2, 0.5)));
        parent = "link_3_adapter";
      }
    }
    joints.add(TestArms.fixed("joint_6-flange", "link_6", "flange", TestArms.v(0, 0, 0), TestArms.v(0, 0, 0)));
    String text = TestArms.urdf("m10", joints, l -> l.equals("base_link")
        ? "    <!-- the base -->\n    <visual><geometry><mesh filename=\"package://m_support/meshes/BASE_LINK.STL\"/></geometry></visual>\n" : "")
        .replace("<axis xyz=\"1.0 0.0 0.0\"/>", "");
    Path file = pkg.resolve("urdf/m10.urdf");
    TestArms.write(file, text);
    assertThat(text).doesNotContain("<axis xyz=\"1.0 0.0 0.0\"/>");
    UrdfImporter.Result r = UrdfImporter.importRobot(file, Map.of());
    assertSameFk(r.model(), joints.subList(1, joints.size()), "flange");
    assertThat(r.notes()).contains("flange: link 'flange'", "link 'world' includes [base_link] (fixed joints)");
    assertBounds(r.model().links().get(0).meshes().get(0), new double[] {-100, -100, 0}, new double[] {100, 100, 200});
  }

  @Test
  void limitsAreConvertedOnceAndAContinuousJointGetsPlusMinus360() throws Exception {
    RobotModel m = UrdfImporter.importRobot(sphericalArm(), extraPackage()).model();
    assertThat(m.joint(1).lowerRad()).isEqualTo(-1.74);
    assertThat(m.joint(1).upperRad()).isEqualTo(2.53);
    assertThat(m.joint(1).maxSpeedRadPerSec()).isEqualTo(6.63);
    assertThat(m.joint(5).lowerRad()).isEqualTo(-2 * Math.PI);
    assertThat(m.joint(5).upperRad()).isEqualTo(2 * Math.PI);
    assertThat(m.joint(5).maxSpeedRadPerSec()).isEqualTo(17.45);
    assertThat(m.coupledJ3()).isFalse();
  }

  @Test
  void worldSitsOnTheJ1AxisAtJ2HeightAsOnAFanucArm() throws Exception {
    Transform arm = UrdfImporter.importRobot(sphericalArm(), extraPackage()).model().X_WB();
    assertThat(arm.distanceTo(Transform.translation(0, 0, -330))).isLessThan(1e-9);
    assertThat(arm.rotationAngleTo(Transform.IDENTITY)).isZero();
    Transform ur = UrdfImporter.importRobot(TestArms.offsetPackage(tmp), Map.of()).model().X_WB();
    assertThat(ur.z()).isCloseTo(-89.159, within(1e-9));
    assertThat(ur.x()).isZero();
  }

  // Method: bounds of each display mesh in its robot link's frame against the mesh numbers
  // written above (unit, up axis, scale and visual origin applied). Tolerance 0.01 mm (floats).
  @Test
  void meshesArriveInMillimetresWithUnitsUpAxisScaleAndOriginApplied() throws Exception {
    RobotModel m = UrdfImporter.importRobot(sphericalArm(), extraPackage()).model();
    assertBounds(m.links().get(0).meshes().get(0), new double[] {-90, -90, 0}, new double[] {90, 90, 330});
    assertBounds(m.links().get(1).meshes().get(0), new double[] {-60, -60, -100}, new double[] {100, 60, 30});
    assertBounds(m.links().get(2).meshes().get(0), new double[] {-50, -50, -20}, new double[] {50, 50, 360});
    assertBounds(m.links().get(4).meshes().get(0), new double[] {50, -30, -20}, new double[] {300, 30, 40});
    // link_5: a cylinder along z (mm file, scale 0.001) turned +90° about x: along -y.
    assertBounds(m.links().get(5).meshes().get(0), new double[] {-30, -40, -30}, new double[] {30, 40, 30});
    // link_3 merges the cover (orange, its own mesh) behind a fixed joint; link_6's grey flange.
    assertThat(m.links().get(3).meshes()).extracting(LinkMesh::color).containsExactly("body", "#ff8000");
    assertThat(m.links().get(6).meshes()).extracting(LinkMesh::color).containsExactly("#999999");
  }

  @Test
  void collisionPrimitivesStayAndMeshesGetTightBoxes() throws Exception {
    UrdfImporter.Result r = UrdfImporter.importRobot(sphericalArm(), extraPackage());
    RobotModel m = r.model();
    assertThat(m.links().get(0).shapes()).singleElement().isInstanceOf(LinkShape.Cylinder.class);
    LinkShape.Box b1 = (LinkShape.Box) m.links().get(1).shapes().get(0);
    assertThat(b1.size().x()).isCloseTo(160, within(1e-9));
    assertThat(b1.X_LS().z()).isCloseTo(-35, within(1e-9));
    LinkShape.Box sphere = (LinkShape.Box) m.links().get(2).shapes().get(0);
    assertThat(sphere.size().x()).isCloseTo(120, within(1e-9));
    // link_3: a box mesh turned by three angles; the fitted box must be the box itself (120 x 100 x 110 mm).
    UrdfImporter.BodyReport fit3 = r.bodies().stream().filter(b -> b.link().equals("link_3")).findFirst().orElseThrow();
    assertThat(fit3.source()).contains("collision mesh");
    assertThat(fit3.hullVolumeMm3()).isCloseTo(120 * 100 * 110, within(1.0));
    assertThat(fit3.ratio()).isCloseTo(1.0, within(1e-4));
    // link_5: a 32-sided cylinder: its box is the square prism around it, 4/π of the round one (1.27).
    UrdfImporter.BodyReport fit5 = r.bodies().stream().filter(b -> b.link().equals("link_5")).findFirst().orElseThrow();
    assertThat(fit5.source()).isEqualTo("fitted to visual meshes");
    assertThat(fit5.ratio()).isBetween(1.26, 1.30);
    for (UrdfImporter.BodyReport b : r.bodies()) {
      System.out.printf(java.util.Locale.ROOT, "spherical arm body %-8s %-55s box %10.1f cm3 hull %10.1f cm3 ratio %.3f%n",
          b.link(), b.source(), b.boxVolumeMm3() / 1000, b.hullVolumeMm3() / 1000, b.ratio());
    }
  }

  @Test
  void theWrittenRobotFolderLoadsBackWithTheSameKinematicsAndMeshes() throws Exception {
    UrdfImporter.Result r = UrdfImporter.importRobot(sphericalArm(), extraPackage());
    Path out = tmp.resolve("robots/test_arm");
    Path json = RobotFileWriter.write(r.model(), "test", out);
    assertThat(json).isEqualTo(out.resolve("test_arm.json"));
    RobotModel back = RobotDefinitions.loadFile(json);
    assertSameFk(back, TestArms.sphericalJoints(), "tool0");
    for (int i = 0; i <= 6; i++) {
      assertThat(back.links().get(i).meshes()).hasSameSizeAs(r.model().links().get(i).meshes());
      assertThat(back.links().get(i).shapes()).hasSameSizeAs(r.model().links().get(i).shapes());
    }
    assertBounds(back.links().get(4).meshes().get(0), new double[] {50, -30, -20}, new double[] {300, 30, 40});
    try (Stream<Path> s = Files.list(tmp.resolve("robots"))) {
      assertThat(s.map(p -> p.getFileName().toString())).containsExactly("test_arm");
    }
    // A second import into the same folder is refused and leaves the first whole.
    assertThatThrownBy(() -> RobotFileWriter.write(r.model(), "test", out)).hasMessageContaining("already exists");
    assertThat(RobotDefinitions.loadFile(json).links().get(4).meshes()).hasSize(1);
  }

  @Test
  void aScenarioMayNameTheUrdfOrTheImportedJsonRelativeToItself() throws Exception {
    Path urdf = sphericalArm();
    Files.createDirectories(tmp.resolve("elsewhere/extra"));
    // The scenario names the URDF; the 'extra' package cannot be given there, so point its mesh at a file path.
    String text = Files.readString(urdf).replace("package://extra/link_4.dae", "file://" + tmp.resolve("elsewhere/extra/link_4.dae"));
    Files.writeString(urdf, text);
    Path scenario = tmp.resolve("ws/cell.json");
    Files.writeString(scenario, """
        {"format": 1, "robots": [{"name": "robot1", "model": "src/arm_support/urdf/test_arm.urdf", "jointsDeg": [0, 0, 0, 0, 0, 0]}]}
        """);
    ScenarioLoad load = ScenarioReader.read(scenario);
    assertThat(load).isInstanceOf(ScenarioLoad.Loaded.class);
    String ref = ((ScenarioLoad.Loaded) load).scenario().robots().get(0).modelId();
    assertThat(Path.of(ref)).isEqualTo(urdf.toAbsolutePath().normalize());
    assertSameFk(RobotDefinitions.load(ref), TestArms.sphericalJoints(), "tool0");
    String written = ScenarioWriter.toJson(((ScenarioLoad.Loaded) load).scenario(), scenario.getParent());
    assertThat(written).contains("\"model\" : \"src/arm_support/urdf/test_arm.urdf\"");
  }

  // ---- refusals: one line naming the file and the reason, nothing written ----

  /** A valid 6-joint URDF text with simple links (no meshes). */
  private static String plain(List<TestArms.J> joints) {
    return TestArms.urdf("plain", joints, l -> "    <collision><geometry><box size=\"0.1 0.1 0.1\"/></geometry></collision>\n");
  }

  private static List<TestArms.J> sixJoints() {
    List<TestArms.J> j = new ArrayList<>();
    String parent = "base_link";
    for (int i = 1; i <= 6; i++) {
      String child = "link_" + i;
      j.add(TestArms.rev("joint_" + i, parent, child, TestArms.v(0, 0, 0.1), TestArms.v(0, i % 2, (i + 1) % 2), -3, 3, 5));
      parent = child;
    }
    return j;
  }

  @Test
  void limitsAndSpeedsBeyondWhatARobotFileTakesAreLimitedWithANoteAndTheWrittenFileLoads() throws Exception {
    List<TestArms.J> wide = new ArrayList<>(sixJoints());
    // J6 from -25 to 25 rad (about ±1432°) at 100 rad/s (about 5730°/s)
    wide.set(5, TestArms.rev("joint_6", "link_5", "link_6", TestArms.v(0, 0, 0.1), TestArms.v(0, 0, 1), -25, 25, 100));
    Path file = tmp.resolve("wide/wide.urdf");
    TestArms.write(file, plain(wide));
    UrdfImporter.Result r = UrdfImporter.importRobot(file, Map.of());
    assertThat(r.notes()).contains("joint 'joint_6' turns beyond ±1080°: limited to ±1080°",
        "joint 'joint_6' gives velocity 5730°/s: limited to 3600°/s");
    var j6 = r.model().joints().get(5);
    assertThat(Math.toDegrees(j6.upperRad())).isCloseTo(1080, within(1e-9));
    assertThat(Math.toDegrees(j6.lowerRad())).isCloseTo(-1080, within(1e-9));
    assertThat(Math.toDegrees(j6.maxSpeedRadPerSec())).isCloseTo(3600, within(1e-9));
    Path json = RobotFileWriter.write(r.model(), "x", tmp.resolve("wide-out"));
    var back = RobotDefinitions.loadFile(json);
    assertThat(Math.toDegrees(back.joints().get(5).upperRad())).isCloseTo(1080, within(1e-9));
  }

  private String refusal(String name, String urdfText) throws Exception {
    Path file = tmp.resolve("bad/" + name);
    TestArms.write(file, urdfText);
    Path out = tmp.resolve("out-" + name);
    try {
      UrdfImporter.Result r = UrdfImporter.importRobot(file, Map.of());
      RobotFileWriter.write(r.model(), "x", out);
    } catch (FileFormatException e) {
      assertThat(out).doesNotExist();
      assertThat(e.getMessage()).startsWith(file.toString()).doesNotContain("\n");
      return e.getMessage();
    }
    throw new AssertionError(name + " was imported");
  }

  @Test
  void fiveOrSevenMovingJointsAreRefused() throws Exception {
    assertThat(refusal("five.urdf", plain(sixJoints().subList(0, 5))))
        .contains("not a serial 6-axis arm: 5 moving joints from 'base_link' to 'link_5'").contains("exactly 6");
    List<TestArms.J> seven = new ArrayList<>(sixJoints());
    seven.add(TestArms.rev("joint_7", "link_6", "link_7", TestArms.v(0, 0, 0.1), TestArms.v(0, 0, 1), -3, 3, 5));
    assertThat(refusal("seven.urdf", plain(seven))).contains("7 moving joints").contains("joint_7");
  }

  @Test
  void aTreeAndALoopAreRefused() throws Exception {
    List<TestArms.J> tree = new ArrayList<>(sixJoints());
    tree.add(TestArms.rev("finger", "link_3", "side", TestArms.v(0, 0, 0.1), TestArms.v(0, 0, 1), -1, 1, 1));
    assertThat(refusal("tree.urdf", plain(tree))).contains("link 'link_3' branches into joints 'joint_4' and 'finger'").contains("tree");
    List<TestArms.J> loop = new ArrayList<>(sixJoints());
    loop.add(TestArms.fixed("closing", "link_6", "link_2", TestArms.v(0, 0, 0), TestArms.v(0, 0, 0)));
    assertThat(refusal("loop.urdf", plain(loop))).matches(".*loop.urdf:\\d+: .*link 'link_2' is the child of joint 'joint_2'.*loop");
  }

  @Test
  void aMissingMeshABadNumberAndAnUnknownParentNameTheirLine() throws Exception {
    String missing = TestArms.urdf("m", sixJoints(), l -> l.equals("link_2")
        ? "    <visual><geometry><mesh filename=\"meshes/nothere.stl\"/></geometry></visual>\n" : "");
    assertThat(refusal("missing.urdf", missing)).matches(".*missing.urdf:\\d+: mesh 'meshes/nothere.stl' not found \\(looked for .*nothere.stl\\)");
    String badNumber = plain(sixJoints()).replace("<origin xyz=\"0.0 0.0 0.1\"", "<origin xyz=\"0.0 0.0 0.1x\"");
    String msg = refusal("number.urdf", badNumber);
    int line = lineOf(badNumber, "0.1x");
    assertThat(msg).isEqualTo(tmp.resolve("bad/number.urdf") + ":" + line
        + ": joint 'joint_1' <origin> xyz: expected 3 numbers (metres) separated by spaces, got \"0.0 0.0 0.1x\"");
    String unknownParent = plain(sixJoints()).replace("<parent link=\"link_3\"/>", "<parent link=\"link_33\"/>");
    assertThat(refusal("parent.urdf", unknownParent))
        .startsWith(tmp.resolve("bad/parent.urdf") + ":" + lineOf(unknownParent, "link_33") + ": joint 'joint_4' <parent>: unknown link 'link_33'");
    String unknownPackage = TestArms.urdf("p", sixJoints(), l -> l.equals("link_1")
        ? "    <visual><geometry><mesh filename=\"package://nowhere/a.stl\"/></geometry></visual>\n" : "");
    assertThat(refusal("package.urdf", unknownPackage)).contains("package 'nowhere' not found (give --package nowhere=DIR");
    Files.writeString(tmp.resolve("bad/broken.dae"), "<COLLADA>not really</COLLADA>");
    String corrupt = TestArms.urdf("c", sixJoints(), l -> l.equals("link_4")
        ? "    <collision><geometry><mesh filename=\"broken.dae\"/></geometry></collision>\n" : "");
    assertThat(refusal("corrupt.urdf", corrupt)).matches(".*corrupt.urdf:" + lineOf(corrupt, "broken.dae")
        + ": mesh 'broken.dae': .*broken.dae: (not a readable mesh|the mesh holds no triangles).*");
  }

  @Test
  void xacroAndPrismaticAndBadLimitsAreRefused() throws Exception {
    String xacro = plain(sixJoints()).replace("<robot name=\"plain\">",
        "<robot name=\"plain\" xmlns:xacro=\"http://www.ros.org/wiki/xacro\">\n  <xacro:property name=\"l\" value=\"0.1\"/>");
    assertThat(refusal("arm.urdf", xacro)).contains("is a xacro file").contains("xacro arm.urdf > arm_expanded.urdf");
    Path x = tmp.resolve("bad/arm.urdf.xacro");
    TestArms.write(x, xacro);
    assertThatThrownBy(() -> UrdfImporter.importRobot(x, Map.of())).hasMessage(x
        + ": is a xacro file, which RobotRun does not expand; expand it first with ROS's xacro tool (xacro arm.urdf.xacro > arm.urdf) and import arm.urdf");
    List<TestArms.J> prismatic = new ArrayList<>(sixJoints());
    TestArms.J j3 = prismatic.get(2);
    prismatic.set(2, new TestArms.J(j3.name(), "prismatic", j3.parent(), j3.child(), j3.xyz(), j3.rpy(), j3.axis(), 0, 0.5, 1));
    assertThat(refusal("prismatic.urdf", plain(prismatic))).contains("joint 'joint_3' is prismatic");
    String badLimit = plain(sixJoints()).replaceFirst("lower=\"-3.0\" upper=\"3.0\"", "lower=\"3.0\" upper=\"-3.0\"");
    assertThat(refusal("limit.urdf", badLimit)).contains("joint 'joint_1' <limit>: expected lower below upper");
    String floating = plain(sixJoints()).replaceFirst("type=\"revolute\"", "type=\"floating\"");
    assertThat(refusal("floating.urdf", floating)).contains("type 'floating' is not supported");
  }

  private static int lineOf(String text, String needle) {
    String[] lines = text.split("\n", -1);
    for (int i = 0; i < lines.length; i++) {
      if (lines[i].contains(needle)) {
        return i + 1;
      }
    }
    throw new AssertionError(needle);
  }

  // ---- helpers ----

  static void assertSameFk(RobotModel m, List<TestArms.J> joints, String flangeLink) {
    List<String> linkNames = new ArrayList<>();
    linkNames.add(joints.get(0).parent());
    for (TestArms.J j : joints) {
      if (j.moving()) {
        linkNames.add(j.child());
      }
    }
    Random rnd = new Random(24);
    for (int trial = 0; trial <= 200; trial++) {
      double[] q = new double[6];
      for (int i = 0; i < 6 && trial > 0; i++) {
        q[i] = m.joint(i).lowerRad() + rnd.nextDouble() * (m.joint(i).upperRad() - m.joint(i).lowerRad());
      }
      Transform[] X_BL = ForwardKinematics.linkPosesInBase(m, q);
      for (int i = 0; i <= 6; i++) {
        assertClose(X_BL[i], TestArms.pose(joints, linkNames.get(i), q), "link " + linkNames.get(i));
      }
      assertClose(ForwardKinematics.flangePoseInBase(m, q), TestArms.pose(joints, flangeLink, q), "flange");
    }
  }

  private static void assertClose(Transform X, double[][] expected, String what) {
    double[] got = {X.r00(), X.r01(), X.r02(), X.x(), X.r10(), X.r11(), X.r12(), X.y(), X.r20(), X.r21(), X.r22(), X.z()};
    for (int r = 0; r < 3; r++) {
      for (int c = 0; c < 4; c++) {
        double tol = c == 3 ? 1e-6 : 1e-9;
        assertThat(got[r * 4 + c]).as("%s [%d][%d]", what, r, c).isCloseTo(expected[r][c], within(tol));
      }
    }
  }

  private static void assertBounds(LinkMesh m, double[] lo, double[] hi) {
    float[] t = m.triangles();
    double[] min = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE};
    double[] max = {-Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
    for (int i = 0; i < t.length; i++) {
      min[i % 3] = Math.min(min[i % 3], t[i]);
      max[i % 3] = Math.max(max[i % 3], t[i]);
    }
    for (int k = 0; k < 3; k++) {
      assertThat(min[k]).as("%s min[%d]", m.key(), k).isCloseTo(lo[k], within(0.01));
      assertThat(max[k]).as("%s max[%d]", m.key(), k).isCloseTo(hi[k], within(0.01));
    }
  }
}
