package org.robotrun.io;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.InputStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;
import org.robotrun.robot.ClosedFormIk;
import org.robotrun.robot.Config;
import org.robotrun.robot.ForwardKinematics;
import org.robotrun.robot.IkResult;
import org.robotrun.robot.IkSolver;
import org.robotrun.robot.RobotModel;

/**
 * FANUC arms written as URDF in the layouts real packages use (ROS-Industrial's
 * {@code fanuc_*_support}: base_link, link_1..link_6, flange, tool0; FANUC's own descriptions
 * with every joint about its z; a flange link without tool0; a turned or moved base), built here
 * from the chain numbers in {@code tests/resources/robots/chain-facts.json}. Every one must get
 * the OPW closed form (base and flange corrections where the frames are not OPW's) and round
 * trip 2000 targets in the ground truth's CONFIG, inside the limits.
 */
public class RosIndustrialLayoutTest {
  static final JsonNode FACTS = readFacts();

  @TempDir
  Path tmp;

  private static JsonNode readFacts() {
    try (InputStream in = RosIndustrialLayoutTest.class.getResourceAsStream("/robots/chain-facts.json")) {
      return new ObjectMapper().readTree(in).get("models");
    } catch (Exception e) {
      throw new IllegalStateException(e);
    }
  }

  /** Layouts: whether the flange (tool0 or flange) is turned against OPW's, and the base's placement. */
  enum Layout {
    /** fanuc_*_support: tool0 turned rpy (π, -π/2, 0) from flange; base_link on the floor. */
    ROS_I(false),
    /** Only the {@code flange} link (z up at q = 0, across J6): needs a flange correction. */
    FLANGE_ONLY(true),
    /** Every joint turns about its own z, origins rotated (FANUC's own descriptions' style). */
    Z_AXES(false),
    /** A fixed world → base_link turned 90° about y (wall mount). */
    WALL(true),
    /** base_link under a world link turned 180° about x (ceiling mount). */
    CEILING(false),
    /** base_link moved and turned about z (an arm placed off the origin). */
    OFFSET_BASE(true);

    final boolean corrected;

    Layout(boolean corrected) {
      this.corrected = corrected;
    }
  }

  static Stream<Arguments> cases() {
    List<Arguments> out = new ArrayList<>();
    for (String id : List.of("lrmate200id", "m10ia", "r2000ic165f")) {
      for (Layout l : Layout.values()) {
        out.add(Arguments.of(id, l));
      }
    }
    return out.stream();
  }

  @ParameterizedTest(name = "{0} {1}")
  @MethodSource("cases")
  void everyLayoutGetsTheClosedFormAndRoundTripsInItsConfig(String id, Layout layout) throws Exception {
    Path file = tmp.resolve(id + "_" + layout + ".urdf");
    TestArms.write(file, urdf(FACTS.get(id), id, layout));
    RobotModel model = UrdfImporter.importRobot(file, Map.of()).model();
    assertThat(model.opw()).as("%s %s: OPW detected", id, layout).isPresent();
    // Corrections appear only where the frames need them (and the library's own layout needs none).
    assertThat(model.opw().get().corrected()).as("%s %s corrected", id, layout).isEqualTo(layout.corrected);
    IkSolver solver = IkSolver.forModel(model);
    assertThat(solver.kind()).isEqualTo(ClosedFormIk.KIND);
    roundTrip(model, solver, 2000, 24 + layout.ordinal());
  }

  @Test
  void theParametersOfATurnedLayoutAreThePublishedOnes() throws Exception {
    Path file = tmp.resolve("wall.urdf");
    TestArms.write(file, urdf(FACTS.get("m10ia"), "m10ia", Layout.WALL));
    var p = UrdfImporter.importRobot(file, Map.of()).model().opw().orElseThrow();
    // ROS-I opw_parameters_m10ia.yaml: a1 150, a2 -200, b 0, c1 450, c2 600, c3 640, c4 100.
    assertThat(new double[] {p.a1(), p.a2(), p.b(), p.c1(), p.c2(), p.c3(), p.c4()})
        .containsExactly(new double[] {150, -200, 0, 450, 600, 640, 100}, org.assertj.core.data.Offset.offset(1e-9));
  }

  @Test
  void anglesRoundedToFourDecimalsStillGetTheClosedFormFinishedOnTheChain() throws Exception {
    // FANUC-style file with every joint about z and its origins' rpy written as 1.5708, -1.5708,
    // 3.1416: the axes are 4e-6 rad off OPW's, so the parameters are approximate and each answer
    // is finished by Newton steps on the chain.
    String text = urdf(FACTS.get("m20ia"), "m20ia", Layout.Z_AXES);
    java.util.regex.Matcher mm = java.util.regex.Pattern.compile("rpy=\"([^\"]*)\"").matcher(text);
    StringBuilder rounded = new StringBuilder();
    while (mm.find()) {
      StringBuilder r = new StringBuilder();
      for (String v : mm.group(1).split(" ")) {
        r.append(r.isEmpty() ? "" : " ").append(String.format(java.util.Locale.ROOT, "%.4f", Double.parseDouble(v)));
      }
      mm.appendReplacement(rounded, "rpy=\"" + r + "\"");
    }
    mm.appendTail(rounded);
    assertThat(rounded.toString()).contains("1.5708");
    Path file = tmp.resolve("rounded.urdf");
    TestArms.write(file, rounded.toString());
    RobotModel model = UrdfImporter.importRobot(file, Map.of()).model();
    assertThat(model.opw()).isPresent();
    assertThat(model.opw().get().approximate()).isTrue();
    IkSolver solver = IkSolver.forModel(model);
    assertThat(solver.kind()).isEqualTo(ClosedFormIk.KIND);
    roundTrip(model, solver, 500, 5);
    // The exact file is not approximate.
    TestArms.write(file, text);
    assertThat(UrdfImporter.importRobot(file, Map.of()).model().opw().get().approximate()).isFalse();
  }

  @Test
  void aToolFrameWrittenToEightDecimalsKeepsTheExactClosedForm() throws Exception {
    // ROS-I's tool0 written as rpy="3.14159265 -1.57079633 0": the flange's z is 3e-9..3e-8 rad off
    // J6's axis. The joint axes are exact, so the constant flange correction carries the tilt and
    // the parameters stay exact (a tilt read from 1 - r22 was lost and sent the arm to the
    // approximate path with Newton steps, twice as slow).
    String text = urdf(FACTS.get("lrmate200id"), "lrmate200id", Layout.ROS_I);
    java.util.regex.Matcher mm = java.util.regex.Pattern
        .compile("(<child link=\"tool0\"/><origin xyz=\"[^\"]*\" rpy=\")([^\"]*)\"").matcher(text);
    assertThat(mm.find()).as("the tool0 joint in %s", text).isTrue();
    StringBuilder r = new StringBuilder();
    for (String v : mm.group(2).split(" ")) {
      r.append(r.isEmpty() ? "" : " ").append(String.format(java.util.Locale.ROOT, "%.8f", Double.parseDouble(v)));
    }
    String rounded = text.substring(0, mm.start(2)) + r + text.substring(mm.end(2));
    assertThat(rounded).isNotEqualTo(text);
    Path file = tmp.resolve("tool0_8.urdf");
    TestArms.write(file, rounded);
    RobotModel model = UrdfImporter.importRobot(file, Map.of()).model();
    assertThat(model.opw()).isPresent();
    assertThat(model.opw().get().approximate()).isFalse();
    assertThat(model.opw().get().corrected()).isTrue();
    IkSolver solver = IkSolver.forModel(model);
    assertThat(solver.kind()).isEqualTo(ClosedFormIk.KIND);
    roundTrip(model, solver, 500, 8);
  }

  @Test
  void aWristWhoseAxesMissOnePointIsNotTakenForOpwEvenWithCorrections() throws Exception {
    Path file = tmp.resolve("offset6.urdf");
    // J6 moved 20 mm sideways: no wrist centre, so no closed form (the derivation must not
    // hide that in a flange correction).
    String text = urdf(FACTS.get("lrmate200id"), "lrmate200id", Layout.FLANGE_ONLY)
        .replace("<origin xyz=\"0.0 0.0 0.0\" rpy=\"0.0 0.0 0.0\"/><axis xyz=\"-1.0 0.0 0.0\"/><limit lower=\"-6.283",
            "<origin xyz=\"0.0 0.02 0.0\" rpy=\"0.0 0.0 0.0\"/><axis xyz=\"-1.0 0.0 0.0\"/><limit lower=\"-6.283");
    assertThat(text).contains("0.0 0.02 0.0");
    TestArms.write(file, text);
    RobotModel model = UrdfImporter.importRobot(file, Map.of()).model();
    assertThat(model.opw()).isEmpty();
    assertThat(IkSolver.forModel(model).kind()).isNotEqualTo(ClosedFormIk.KIND);
  }

  /** Random in-limit joints → FK → solve in their CONFIG: same CONFIG, in limits, same pose; nearest = itself. */
  static void roundTrip(RobotModel model, IkSolver solver, int full, long seed) {
    // Under mutation testing a tenth of the targets (the first of the same seeded sequence).
    int n = org.robotrun.PitScale.samples(full, Math.max(20, full / 10));
    Random rnd = new Random(seed);
    double[] home = new double[6];
    for (int k = 0; k < n; k++) {
      double[] q = new double[6];
      for (int i = 0; i < 6; i++) {
        q[i] = model.joint(i).lowerRad() + rnd.nextDouble() * (model.joint(i).upperRad() - model.joint(i).lowerRad());
      }
      Transform x = ForwardKinematics.flangePoseInBase(model, q);
      Config c = solver.configOf(q);
      IkResult r = solver.solve(x, c, home);
      assertThat(r).as("%s target %d (%s)", model.id(), k, c).isInstanceOf(IkResult.Solved.class);
      double[] a = ((IkResult.Solved) r).q();
      Transform y = ForwardKinematics.flangePoseInBase(model, a);
      assertThat(y.distanceTo(x)).as("%s target %d", model.id(), k).isLessThan(1e-6);
      assertThat(y.rotationAngleTo(x)).as("%s target %d", model.id(), k).isLessThan(1e-9);
      assertThat(model.firstJointOutsideLimits(a)).as("%s target %d in limits", model.id(), k).isEqualTo(-1);
      assertThat(solver.configOf(a)).as("%s target %d CONFIG", model.id(), k).isEqualTo(c);
      IkResult near = solver.solveNearest(x, q);
      double[] b = ((IkResult.Solved) near).q();
      for (int i = 0; i < 6; i++) {
        assertThat(b[i]).as("%s target %d nearest J%d", model.id(), k, i + 1).isCloseTo(q[i], org.assertj.core.data.Offset.offset(1e-6));
      }
    }
  }

  // ---- writing the layouts ----------------------------------------------------------------

  /** Writes one chain of the facts in one layout (for other tests). */
  public static void writeLayout(Path file, String id, String layout) throws java.io.IOException {
    TestArms.write(file, urdf(FACTS.get(id), id, Layout.valueOf(layout)));
  }

  /** The URDF of one chain in one layout (metres, radians), numbers from the chain facts. */
  static String urdf(JsonNode m, String id, Layout layout) {
    JsonNode js = m.get("joints");
    Transform[] origin = new Transform[6];
    Vec3[] axis = new Vec3[6];
    for (int i = 0; i < 6; i++) {
      JsonNode j = js.get(i);
      origin[i] = Transform.fromRpy(j.get("xyz").get(0).asDouble(), j.get("xyz").get(1).asDouble(), j.get("xyz").get(2).asDouble(),
          Math.toRadians(j.get("rpy").get(0).asDouble()), Math.toRadians(j.get("rpy").get(1).asDouble()),
          Math.toRadians(j.get("rpy").get(2).asDouble()));
      axis[i] = new Vec3(j.get("axis").get(0).asDouble(), j.get("axis").get(1).asDouble(), j.get("axis").get(2).asDouble());
    }
    JsonNode f = m.get("flange");
    Transform flangeXyz = Transform.translation(f.get("xyz").get(0).asDouble(), f.get("xyz").get(1).asDouble(), f.get("xyz").get(2).asDouble());
    Transform tool0 = Transform.fromRpy(0, 0, 0, Math.toRadians(f.get("rpy").get(0).asDouble()),
        Math.toRadians(f.get("rpy").get(1).asDouble()), Math.toRadians(f.get("rpy").get(2).asDouble()));
    if (layout == Layout.Z_AXES) {
      // Link i's frame turned by A_i (z onto the joint axis): X'_PJ = A_(i-1)⁻¹ · X_PJ · A_i, axis z.
      Transform prev = Transform.IDENTITY;
      for (int i = 0; i < 6; i++) {
        Transform a = onto(axis[i]);
        origin[i] = prev.inverse().compose(origin[i]).compose(a);
        axis[i] = Vec3.Z;
        prev = a;
      }
      flangeXyz = prev.inverse().compose(flangeXyz);
    }
    StringBuilder s = new StringBuilder("<?xml version=\"1.0\"?>\n<robot name=\"" + id + "_" + layout.name().toLowerCase() + "\">\n");
    List<String> links = new ArrayList<>(List.of("base_link", "link_1", "link_2", "link_3", "link_4", "link_5", "link_6", "flange", "base"));
    if (layout != Layout.FLANGE_ONLY) {
      links.add("tool0");
    }
    if (layout == Layout.WALL || layout == Layout.CEILING || layout == Layout.OFFSET_BASE) {
      links.add(0, "world");
      Transform mount = switch (layout) {
        case WALL -> Transform.fromRpy(0, 0, 1200, 0, Math.PI / 2, 0);
        case CEILING -> Transform.fromRpy(0, 0, 2500, Math.PI, 0, 0);
        default -> Transform.fromRpy(300, -200, 100, 0, 0, 0.7);
      };
      fixedJoint(s, "world-base_link", "world", "base_link", mount);
    }
    for (String l : links) {
      s.append("  <link name=\"").append(l).append("\"/>\n");
    }
    fixedJoint(s, "base_link-base", "base_link", "base", Transform.translation(0, 0, m.get("worldZ").asDouble()));
    for (int i = 0; i < 6; i++) {
      JsonNode j = js.get(i);
      double[] rpy = rpy(origin[i]);
      s.append("  <joint name=\"joint_").append(i + 1).append("\" type=\"revolute\"><parent link=\"")
          .append(i == 0 ? "base_link" : "link_" + i).append("\"/><child link=\"link_").append(i + 1).append("\"/>")
          .append("<origin xyz=\"").append(m(origin[i].x())).append(' ').append(m(origin[i].y())).append(' ').append(m(origin[i].z()))
          .append("\" rpy=\"").append(rpy[0]).append(' ').append(rpy[1]).append(' ').append(rpy[2]).append("\"/>")
          .append("<axis xyz=\"").append(axis[i].x()).append(' ').append(axis[i].y()).append(' ').append(axis[i].z()).append("\"/>")
          .append("<limit lower=\"").append(Math.toRadians(j.get("lower").asDouble())).append("\" upper=\"")
          .append(Math.toRadians(j.get("upper").asDouble())).append("\" effort=\"0\" velocity=\"")
          .append(Math.toRadians(j.get("maxVelocity").asDouble())).append("\"/></joint>\n");
    }
    fixedJoint(s, "joint_6-flange", "link_6", "flange", flangeXyz);
    if (layout != Layout.FLANGE_ONLY) {
      // (With Z_AXES the flange link lands where it always does: A_6⁻¹ is in flangeXyz.)
      fixedJoint(s, "flange-tool0", "flange", "tool0", tool0);
    }
    return s.append("</robot>\n").toString();
  }

  private static void fixedJoint(StringBuilder s, String name, String parent, String child, Transform t) {
    double[] rpy = rpy(t);
    s.append("  <joint name=\"").append(name).append("\" type=\"fixed\"><parent link=\"").append(parent)
        .append("\"/><child link=\"").append(child).append("\"/><origin xyz=\"").append(m(t.x())).append(' ')
        .append(m(t.y())).append(' ').append(m(t.z())).append("\" rpy=\"").append(rpy[0]).append(' ').append(rpy[1])
        .append(' ').append(rpy[2]).append("\"/></joint>\n");
  }

  private static double m(double mm) {
    return mm / 1000 + 0.0;
  }

  /** A rotation taking z onto the unit vector a (about z × a). */
  static Transform onto(Vec3 a) {
    Vec3 c = Vec3.Z.cross(a);
    double s = c.norm();
    double angle = Math.atan2(s, a.z());
    if (s < 1e-12) {
      return a.z() > 0 ? Transform.IDENTITY : Transform.rotation(1, 0, 0, Math.PI);
    }
    return Transform.rotation(c.x() / s, c.y() / s, c.z() / s, angle);
  }

  /** URDF roll, pitch, yaw of a rotation (R = Rz(yaw)·Ry(pitch)·Rx(roll)). */
  static double[] rpy(Transform t) {
    double pitch = Math.asin(Math.max(-1, Math.min(1, -t.r20())));
    if (Math.abs(t.r20()) > 1 - 1e-12) {
      return new double[] {0.0, pitch + 0.0, Math.atan2(-t.r01(), t.r11()) + 0.0};
    }
    return new double[] {Math.atan2(t.r21(), t.r22()) + 0.0, pitch + 0.0, Math.atan2(t.r10(), t.r00()) + 0.0};
  }
}
