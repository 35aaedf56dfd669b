package org.robotrun.io;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * URDF packages written for the importer tests, and an FK of their joint lists that does not
 * use RobotRun's code (4x4 matrices built here from the URDF numbers).
 *
 * <p>The spherical-wrist arm has the proportions of a small FANUC arm (numbers made up for the
 * test); the offset-wrist arm has the published UR5 link lengths (d1 0.089159, a2 0.425,
 * a3 0.39225, d4 0.10915, d5 0.09465, d6 0.0823 m, Universal Robots' DH table), laid out here
 * as URDF joint origins.
 */
public final class TestArms {
  private TestArms() {}

  /** A rotated box (rpy below) used as link_3's COLLADA mesh, in millimetres. */
  static final double[] LINK3_RPY = {0.3, 0.5, 0.7};

  /**
   * Writes the spherical-wrist arm as a ROS workspace: arm_support (URDF, some meshes), a
   * sibling package arm_meshes, and a package elsewhere ("extra") given with --package.
   * Returns the URDF.
   */
  public static Path sphericalPackage(Path tmp) throws Exception {
    Path src = tmp.resolve("ws/src");
    Path support = src.resolve("arm_support");
    Path meshes = src.resolve("arm_meshes");
    Path extra = tmp.resolve("elsewhere/extra");
    packageXml(support, "arm_support");
    packageXml(meshes, "arm_meshes");
    // base: ASCII STL, metres.
    MeshFiles.stlAscii(support.resolve("meshes/visual/base.stl"), MeshFiles.cylinder(0, 0, 0.09, 0, 0.33, 24));
    // link_1: binary STL in the sibling package.
    MeshFiles.stlBinary(meshes.resolve("meshes/link_1.stl"), MeshFiles.box(v(-0.06, -0.06, -0.1), v(0.1, 0.06, 0.03)));
    // link_2: OBJ by a path relative to the URDF.
    MeshFiles.obj(support.resolve("meshes/visual/link_2.obj"), MeshFiles.concat(
        MeshFiles.box(v(-0.04, -0.05, 0), v(0.04, 0.05, 0.36)), MeshFiles.cylinder(0, 0, 0.05, -0.02, 0.02, 16)));
    // link_3: COLLADA in mm, Z_UP, a box turned by LINK3_RPY.
    double[] box3 = MeshFiles.box(v(-60, -50, -40), v(60, 50, 70));
    double[][] r = origin(new double[3], LINK3_RPY);
    double[] turned = new double[box3.length];
    for (int i = 0; i < box3.length; i += 3) {
      for (int k = 0; k < 3; k++) {
        turned[i + k] = r[k][0] * box3[i] + r[k][1] * box3[i + 1] + r[k][2] * box3[i + 2];
      }
    }
    MeshFiles.dae(support.resolve("meshes/visual/link_3.dae"), turned, 0.001, "Z_UP");
    // link_4: COLLADA, metres, Y_UP, in the --package folder: a bar along x from 0.05 to 0.3.
    double[] bar = MeshFiles.box(v(0.05, -0.03, -0.02), v(0.3, 0.03, 0.04));
    double[] yUp = new double[bar.length];
    for (int i = 0; i < bar.length; i += 3) {
      yUp[i] = bar[i];
      yUp[i + 1] = bar[i + 2];
      yUp[i + 2] = -bar[i + 1];
    }
    MeshFiles.dae(extra.resolve("link_4.dae"), yUp, 1.0, "Y_UP");
    // link_5: binary STL written in millimetres, scaled by 0.001 in the URDF.
    MeshFiles.stlBinary(support.resolve("meshes/visual/link_5.stl"), MeshFiles.cylinder(0, 0, 30, -40, 40, 32));
    String urdf = urdf("test_arm", sphericalJoints(), link -> switch (link) {
      case "base_link" -> """
            <visual><geometry><mesh filename="package://arm_support/meshes/visual/base.stl"/></geometry></visual>
            <collision><origin xyz="0 0 0.165"/><geometry><cylinder radius="0.09" length="0.33"/></geometry></collision>
        """;
      case "link_1" -> """
            <visual><geometry><mesh filename="package://arm_meshes/meshes/link_1.stl"/></geometry></visual>
            <collision><origin xyz="0.02 0 -0.035"/><geometry><box size="0.16 0.12 0.13"/></geometry></collision>
        """;
      case "link_2" -> """
            <visual><geometry><mesh filename="../meshes/visual/link_2.obj"/></geometry></visual>
            <collision><origin xyz="0 0 0.33"/><geometry><sphere radius="0.06"/></geometry></collision>
        """;
      case "link_3" -> """
            <visual><geometry><mesh filename="package://arm_support/meshes/visual/link_3.dae"/></geometry></visual>
            <collision><geometry><mesh filename="package://arm_support/meshes/visual/link_3.dae"/></geometry></collision>
        """;
      case "link_3_cover" -> """
            <visual><geometry><box size="0.02 0.03 0.04"/></geometry><material name="orange"/></visual>
        """;
      case "link_4" -> """
            <visual><geometry><mesh filename="package://extra/link_4.dae" scale="1 1 1"/></geometry></visual>
        """;
      case "link_5" -> """
            <visual><origin rpy="1.5707963267948966 0 0"/><geometry><mesh filename="package://arm_support/meshes/visual/link_5.stl" scale="0.001 0.001 0.001"/></geometry></visual>
        """;
      case "link_6" -> """
            <visual><origin xyz="-0.006 0 0" rpy="0 1.5707963267948966 0"/><geometry><cylinder radius="0.025" length="0.012"/></geometry>
              <material name="grey"><color rgba="0.6 0.6 0.6 1"/></material></visual>
        """;
      default -> "";
    });
    Path file = support.resolve("urdf/test_arm.urdf");
    write(file, urdf);
    return file;
  }

  /**
   * Writes the offset-wrist arm as package ur_like_description: each link a box tube with a
   * round housing, in all three formats (STL ASCII and binary, OBJ, COLLADA Z_UP in metres and
   * Y_UP in millimetres); only the base has a collision primitive, the rest get fitted boxes.
   * Returns its URDF.
   */
  public static Path offsetPackage(Path tmp) throws IOException {
    Path pkg = tmp.resolve("ur/ur_like_description");
    packageXml(pkg, "ur_like_description");
    Path m = pkg.resolve("meshes");
    MeshFiles.stlAscii(m.resolve("base.stl"), MeshFiles.cylinder(0, 0, 0.075, 0, 0.06, 32));
    MeshFiles.obj(m.resolve("shoulder.obj"), MeshFiles.concat(
        MeshFiles.cylinder(0, 0, 0.06, -0.06, 0.06, 32), MeshFiles.box(v(-0.045, 0, -0.045), v(0.045, 0.18, 0.045))));
    MeshFiles.dae(m.resolve("upperarm.dae"), MeshFiles.concat(
        MeshFiles.box(v(-0.045, -0.17, -0.045), v(0.045, -0.08, 0.045)),
        MeshFiles.box(v(-0.04, -0.16, -0.04), v(0.04, -0.08, 0.44)),
        MeshFiles.cylinder(0, -0.12, 0.055, 0.38, 0.47, 32)), 1.0, "Z_UP");
    MeshFiles.stlBinary(m.resolve("forearm.stl"), MeshFiles.concat(
        MeshFiles.box(v(-0.035, -0.035, -0.03), v(0.035, 0.035, 0.40)), MeshFiles.cylinder(0, 0.03, 0.045, 0.36, 0.42, 32)));
    double[] w1 = MeshFiles.concat(MeshFiles.box(v(-0.035, -0.02, -0.035), v(0.035, 0.12, 0.035)),
        MeshFiles.cylinder(0, 0.093, 0.04, -0.05, 0.05, 24));
    double[] w1mm = new double[w1.length];
    for (int i = 0; i < w1.length; i += 3) {
      w1mm[i] = w1[i] * 1000;
      w1mm[i + 1] = w1[i + 2] * 1000;
      w1mm[i + 2] = -w1[i + 1] * 1000;
    }
    MeshFiles.dae(m.resolve("wrist1.dae"), w1mm, 0.001, "Y_UP");
    MeshFiles.obj(m.resolve("wrist2.obj"), MeshFiles.concat(MeshFiles.box(v(-0.035, -0.035, -0.02), v(0.035, 0.035, 0.12)),
        MeshFiles.cylinder(0, 0, 0.04, 0.06, 0.13, 24)));
    MeshFiles.stlBinary(m.resolve("wrist3.stl"), MeshFiles.cylinder(0, 0, 0.035, 0, 0.08, 32));
    Map<String, String> visual = Map.of("base_link", "base.stl", "shoulder_link", "shoulder.obj", "upper_arm_link", "upperarm.dae",
        "forearm_link", "forearm.stl", "wrist_1_link", "wrist1.dae", "wrist_2_link", "wrist2.obj", "wrist_3_link", "wrist3.stl");
    Path file = pkg.resolve("urdf/ur_like.urdf");
    write(file, urdf("ur_like", offsetJoints(), link -> {
      if (!visual.containsKey(link)) {
        return "";
      }
      String origin = link.equals("wrist_3_link") ? "<origin rpy=\"-1.5707963267948966 0 0\"/>" : "";
      String mesh = "    <visual>" + origin + "<geometry><mesh filename=\"package://ur_like_description/meshes/" + visual.get(link)
          + "\"/></geometry><material name=\"" + (link.equals("base_link") ? "dark" : "blue") + "\"><color rgba=\""
          + (link.equals("base_link") ? "0.2 0.2 0.2 1" : "0.35 0.55 0.8 1") + "\"/></material></visual>\n";
      return link.equals("base_link")
          ? mesh + "    <collision><origin xyz=\"0 0 0.03\"/><geometry><cylinder radius=\"0.075\" length=\"0.06\"/></geometry></collision>\n"
          : mesh;
    }));
    return file;
  }

  public static Map<String, Path> extraPackage(Path tmp) {
    return Map.of("extra", tmp.resolve("elsewhere/extra"));
  }


  /** One URDF joint as the test writes it: metres and radians. */
  record J(String name, String type, String parent, String child, double[] xyz, double[] rpy, double[] axis,
      double lower, double upper, double velocity) {
    boolean moving() {
      return !type.equals("fixed");
    }
  }

  static J fixed(String name, String parent, String child, double[] xyz, double[] rpy) {
    return new J(name, "fixed", parent, child, xyz, rpy, new double[] {1, 0, 0}, 0, 0, 0);
  }

  static J rev(String name, String parent, String child, double[] xyz, double[] axis, double lower, double upper, double vel) {
    return new J(name, "revolute", parent, child, xyz, new double[3], axis, lower, upper, vel);
  }

  static double[] v(double... d) {
    return d;
  }

  /** The spherical-wrist arm's joints, base_link to tool0. */
  static List<J> sphericalJoints() {
    return List.of(
        fixed("base_link-base", "base_link", "base", v(0, 0, 0), v(0, 0, 0)),
        rev("joint_1", "base_link", "link_1", v(0, 0, 0.33), v(0, 0, 1), -2.96, 2.96, 7.85),
        rev("joint_2", "link_1", "link_2", v(0.05, 0, 0), v(0, 1, 0), -1.74, 2.53, 6.63),
        rev("joint_3", "link_2", "link_3", v(0, 0, 0.33), v(0, -1, 0), -2.45, 4.01, 9.07),
        fixed("link_3-cover", "link_3", "link_3_cover", v(0.02, 0, 0.03), v(0.1, 0.2, 0.3)),
        rev("joint_4", "link_3", "link_4", v(0, 0, 0.035), v(-1, 0, 0), -3.31, 3.31, 9.59),
        rev("joint_5", "link_4", "link_5", v(0.335, 0, 0), v(0, -1, 0), -2.18, 2.18, 9.51),
        new J("joint_6", "continuous", "link_5", "link_6", v(0.08, 0, 0), v(0, 0, 0), v(-1, 0, 0), 0, 0, 17.45),
        fixed("joint_6-flange", "link_6", "flange", v(0, 0, 0), v(0, 0, 0)),
        fixed("flange-tool0", "flange", "tool0", v(0.01, 0, 0), v(Math.PI, -Math.PI / 2, 0)));
  }

  /** The offset-wrist (UR5-like) arm's joints, base_link to tool0; some origins rotated. */
  static List<J> offsetJoints() {
    return List.of(
        new J("shoulder_pan_joint", "revolute", "base_link", "shoulder_link", v(0, 0, 0.089159), v(0, 0, 0), v(0, 0, 1), -6.2832, 6.2832, 3.15),
        new J("shoulder_lift_joint", "revolute", "shoulder_link", "upper_arm_link", v(0, 0.13585, 0), v(0, Math.PI / 2, 0), v(0, 1, 0), -6.2832, 6.2832, 3.15),
        new J("elbow_joint", "revolute", "upper_arm_link", "forearm_link", v(0, -0.1197, 0.425), v(0, 0, 0), v(0, 1, 0), -3.1416, 3.1416, 3.15),
        new J("wrist_1_joint", "revolute", "forearm_link", "wrist_1_link", v(0, 0, 0.39225), v(0, Math.PI / 2, 0), v(0, 1, 0), -6.2832, 6.2832, 3.2),
        new J("wrist_2_joint", "revolute", "wrist_1_link", "wrist_2_link", v(0, 0.093, 0), v(0, 0, 0), v(0, 0, 1), -6.2832, 6.2832, 3.2),
        new J("wrist_3_joint", "revolute", "wrist_2_link", "wrist_3_link", v(0, 0, 0.09465), v(0, 0, 0), v(0, 1, 0), -6.2832, 6.2832, 3.2),
        fixed("ee_fixed_joint", "wrist_3_link", "tool0", v(0, 0.0823, 0), v(-Math.PI / 2, 0, 0)));
  }

  /** Writes a URDF with these joints; {@code linkXml} gives each link's inner XML (may be empty). */
  static String urdf(String name, List<J> joints, java.util.function.Function<String, String> linkXml) {
    List<String> links = new ArrayList<>();
    for (J j : joints) {
      if (!links.contains(j.parent)) {
        links.add(j.parent);
      }
      if (!links.contains(j.child)) {
        links.add(j.child);
      }
    }
    StringBuilder s = new StringBuilder("<?xml version=\"1.0\"?>\n<robot name=\"" + name + "\">\n");
    s.append("  <material name=\"orange\"><color rgba=\"1 0.5 0 1\"/></material>\n");
    for (String l : links) {
      s.append("  <link name=\"").append(l).append("\">\n").append(linkXml.apply(l)).append("  </link>\n");
    }
    for (J j : joints) {
      s.append("  <joint name=\"").append(j.name).append("\" type=\"").append(j.type).append("\">\n");
      s.append("    <parent link=\"").append(j.parent).append("\"/>\n");
      s.append("    <child link=\"").append(j.child).append("\"/>\n");
      s.append("    <origin xyz=\"").append(nums(j.xyz)).append("\" rpy=\"").append(nums(j.rpy)).append("\"/>\n");
      if (j.moving()) {
        s.append("    <axis xyz=\"").append(nums(j.axis)).append("\"/>\n");
        if (j.type.equals("continuous")) {
          s.append("    <limit effort=\"10\" velocity=\"").append(num(j.velocity)).append("\"/>\n");
        } else {
          s.append("    <limit lower=\"").append(num(j.lower)).append("\" upper=\"").append(num(j.upper))
              .append("\" effort=\"10\" velocity=\"").append(num(j.velocity)).append("\"/>\n");
        }
      }
      s.append("  </joint>\n");
    }
    s.append("</robot>\n");
    return s.toString();
  }

  static String nums(double[] d) {
    StringBuilder s = new StringBuilder();
    for (double x : d) {
      s.append(s.isEmpty() ? "" : " ").append(num(x));
    }
    return s.toString();
  }

  static String num(double d) {
    return Double.toString(d);
  }

  static void write(Path file, String text) throws IOException {
    Files.createDirectories(file.getParent());
    Files.writeString(file, text, StandardCharsets.UTF_8);
  }

  static void packageXml(Path dir, String name) throws IOException {
    write(dir.resolve("package.xml"), """
        <?xml version="1.0"?>
        <package format="2">
          <name>%s</name>
          <version>0.1.0</version>
          <description>test package</description>
          <maintainer email="t@example.com">t</maintainer>
          <license>BSD</license>
        </package>
        """.formatted(name));
  }

  // ---- independent FK: row-major 4x4 arrays, metres, composed along the URDF tree ----

  /**
   * Pose of {@code link} in the root link's frame at joint values {@code q} (one per moving
   * joint, in list order), in millimetres.
   */
  static double[][] pose(List<J> joints, String link, double[] q) {
    for (J j : joints) {
      if (j.child.equals(link)) {
        double angle = 0;
        int k = 0;
        for (J m : joints) {
          if (m == j) {
            angle = j.moving() ? q[k] : 0;
          }
          if (m.moving()) {
            k++;
          }
        }
        double[][] parent = pose(joints, j.parent, q);
        double[][] origin = origin(j.xyz, j.rpy);
        double[][] turn = j.moving() ? axisAngle(j.axis, angle) : identity();
        return mul(mul(parent, origin), turn);
      }
    }
    return identity();
  }

  static double[][] origin(double[] xyz, double[] rpy) {
    double[][] rx = {{1, 0, 0, 0}, {0, Math.cos(rpy[0]), -Math.sin(rpy[0]), 0}, {0, Math.sin(rpy[0]), Math.cos(rpy[0]), 0}, {0, 0, 0, 1}};
    double[][] ry = {{Math.cos(rpy[1]), 0, Math.sin(rpy[1]), 0}, {0, 1, 0, 0}, {-Math.sin(rpy[1]), 0, Math.cos(rpy[1]), 0}, {0, 0, 0, 1}};
    double[][] rz = {{Math.cos(rpy[2]), -Math.sin(rpy[2]), 0, 0}, {Math.sin(rpy[2]), Math.cos(rpy[2]), 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    double[][] r = mul(rz, mul(ry, rx));
    r[0][3] = xyz[0] * 1000;
    r[1][3] = xyz[1] * 1000;
    r[2][3] = xyz[2] * 1000;
    return r;
  }

  static double[][] axisAngle(double[] axis, double a) {
    double n = Math.sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    double x = axis[0] / n, y = axis[1] / n, z = axis[2] / n;
    double c = Math.cos(a), s = Math.sin(a), t = 1 - c;
    return new double[][] {
        {t * x * x + c, t * x * y - s * z, t * x * z + s * y, 0},
        {t * x * y + s * z, t * y * y + c, t * y * z - s * x, 0},
        {t * x * z - s * y, t * y * z + s * x, t * z * z + c, 0},
        {0, 0, 0, 1}};
  }

  static double[][] identity() {
    return new double[][] {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
  }

  static double[][] mul(double[][] a, double[][] b) {
    double[][] o = new double[4][4];
    for (int i = 0; i < 4; i++) {
      for (int j = 0; j < 4; j++) {
        for (int k = 0; k < 4; k++) {
          o[i][j] += a[i][k] * b[k][j];
        }
      }
    }
    return o;
  }

  static String fmt(double d) {
    return String.format(Locale.ROOT, "%.6f", d);
  }
}
