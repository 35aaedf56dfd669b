package org.robotrun.io;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.robotrun.math.Transform;
import org.robotrun.math.Vec3;

/**
 * Reads a URDF file into {@link Robot}: links with their visual and collision geometry, joints
 * with origin, axis and limits, each with its line. Metres become millimetres here, once;
 * angles stay radians. Every bad value is a {@link FileFormatException} naming file, line, the
 * element and attribute, and what was expected. xacro files are refused with the command that
 * expands them.
 */
final class UrdfReader {
  /** Largest URDF read (real arms are tens of kB). */
  static final long MAX_FILE_BYTES = 8L << 20;

  private UrdfReader() {}

  /** A parsed URDF. */
  record Robot(String name, Map<String, Link> links, List<Joint> joints) {}

  /** A link: its name, line and geometry, each geometry in the link frame. */
  record Link(String name, int line, List<Geometry> visuals, List<Geometry> collisions) {}

  /** One visual or collision element: where it sits in its link (mm), its shape and colour. */
  record Geometry(int line, Transform X_LG, Shape shape, Optional<String> colorHex) {}

  /** The geometries URDF knows (mm). */
  sealed interface Shape {
    record Box(Vec3 sizeMm) implements Shape {}

    record Cylinder(double radiusMm, double lengthMm) implements Shape {}

    record Sphere(double radiusMm) implements Shape {}

    /** A mesh file as written ({@code package://}, {@code file://} or relative) and its per-axis scale. */
    record Mesh(String filename, Vec3 scale) implements Shape {}
  }

  /**
   * A joint: {@code X_PJ} is the joint (and child link) frame in the parent link frame (mm);
   * limits in rad and rad/s for rotary joints, mm and mm/s for prismatic ones; a missing
   * limit is empty.
   */
  record Joint(String name, String type, int line, String parent, int parentLine, String child, int childLine,
      Transform X_PJ, Vec3 axis, int axisLine, Optional<Limit> limit, boolean mimic) {
    boolean actuated() {
      return !type.equals("fixed");
    }
  }

  /** {@code <limit>}: lower and upper (URDF default 0) and velocity (NaN when absent). */
  record Limit(int line, double lower, double upper, double velocity, boolean hasLower, boolean hasUpper) {}

  static Robot read(Path file) {
    String name = file.toString();
    if (name.toLowerCase(Locale.ROOT).endsWith(".xacro")) {
      throw xacro(name);
    }
    byte[] bytes;
    try {
      bytes = BoundedFiles.read(file, MAX_FILE_BYTES, "URDF files");
    } catch (UnreadableFileException e) {
      throw new FileFormatException(name, 0, e.getMessage());
    } catch (IOException e) {
      throw new FileFormatException(name, 0, "cannot read: " + e.getMessage());
    }
    return parse(name, bytes);
  }

  static Robot parse(String source, byte[] bytes) {
    XmlTree.Element root = XmlTree.parse(source, bytes);
    Optional<String[]> x = xacroUse(root);
    if (x.isPresent()) {
      throw xacro(source, Integer.parseInt(x.get()[0]), x.get()[1]);
    }
    if (!root.name().equals("robot")) {
      throw new FileFormatException(source, root.line(), "expected a <robot> element at the top, got <" + root.name() + ">");
    }
    Values v = new Values(source);
    Map<String, String> materials = new HashMap<>();
    for (XmlTree.Element m : root.children("material")) {
      v.materialColor(m).ifPresent(c -> materials.put(m.attribute("name").orElse(""), c));
    }
    Map<String, Link> links = new LinkedHashMap<>();
    for (XmlTree.Element l : root.children("link")) {
      String linkName = v.name(l, "link");
      if (links.containsKey(linkName)) {
        throw new FileFormatException(source, l.line(), "link '" + linkName + "' is defined twice (first at line "
            + links.get(linkName).line() + ")");
      }
      List<Geometry> visuals = new ArrayList<>();
      for (XmlTree.Element e : l.children("visual")) {
        visuals.add(v.geometry(e, "link '" + linkName + "' <visual>", materials));
      }
      List<Geometry> collisions = new ArrayList<>();
      for (XmlTree.Element e : l.children("collision")) {
        collisions.add(v.geometry(e, "link '" + linkName + "' <collision>", materials));
      }
      links.put(linkName, new Link(linkName, l.line(), visuals, collisions));
    }
    List<Joint> joints = new ArrayList<>();
    Map<String, Integer> jointLines = new HashMap<>();
    for (XmlTree.Element j : root.children("joint")) {
      String jointName = v.name(j, "joint");
      Integer first = jointLines.putIfAbsent(jointName, j.line());
      if (first != null) {
        throw new FileFormatException(source, j.line(), "joint '" + jointName + "' is defined twice (first at line " + first + ")");
      }
      joints.add(v.joint(j, jointName, links));
    }
    return new Robot(root.attribute("name").orElse("robot"), links, joints);
  }

  /** The first xacro construct (document order): its line and what it is; empty when there is none. */
  private static Optional<String[]> xacroUse(XmlTree.Element e) {
    if (e.name().startsWith("xacro:")) {
      return Optional.of(new String[] {String.valueOf(e.line()), "<" + e.name() + ">"});
    }
    for (Map.Entry<String, String> a : e.attributes().entrySet()) {
      if (a.getKey().startsWith("xmlns:xacro")) {
        return Optional.of(new String[] {String.valueOf(e.line()), "<" + e.name() + "> declares xmlns:xacro"});
      }
      if (a.getValue().contains("${") || a.getValue().contains("$(")) {
        return Optional.of(new String[] {String.valueOf(e.line()), "<" + e.name() + "> " + a.getKey() + "=\"" + a.getValue() + "\""});
      }
    }
    for (XmlTree.Element c : e.children()) {
      Optional<String[]> r = xacroUse(c);
      if (r.isPresent()) {
        return r;
      }
    }
    return Optional.empty();
  }

  private static FileFormatException xacro(String source, int line, String what) {
    String base = Path.of(source).getFileName().toString();
    String out = base.replaceAll("(?i)\\.urdf$", "") + "_expanded.urdf";
    return new FileFormatException(source, line, what + ": this is a xacro file, which RobotRun does not expand; expand it first"
        + " with ROS's xacro tool (xacro " + base + " > " + out + ") and import " + out);
  }

  private static FileFormatException xacro(String source) {
    String base = Path.of(source).getFileName().toString();
    String out = base.toLowerCase(Locale.ROOT).endsWith(".xacro")
        ? base.replaceAll("(?i)(\\.urdf)?\\.xacro$", "") + ".urdf"
        : base.replaceAll("(?i)\\.urdf$", "") + "_expanded.urdf";
    return new FileFormatException(source, 0, "is a xacro file, which RobotRun does not expand; expand it first with ROS's xacro tool ("
        + "xacro " + base + " > " + out + ") and import " + out);
  }

  /** Attribute readers that name file, line, element and attribute in every error. */
  private record Values(String source) {
    String name(XmlTree.Element e, String what) {
      String n = e.attribute("name").orElse("").strip();
      if (n.isEmpty()) {
        throw new FileFormatException(source, e.line(), "<" + what + ">: expected a name attribute");
      }
      return n;
    }

    Joint joint(XmlTree.Element j, String name, Map<String, Link> links) {
      String at = "joint '" + name + "'";
      String type = j.attribute("type").orElse("");
      if (!List.of("revolute", "continuous", "prismatic", "fixed").contains(type)) {
        throw new FileFormatException(source, j.line(), at + ": type '" + type
            + "' is not supported: expected revolute, continuous, prismatic or fixed");
      }
      XmlTree.Element parent = j.child("parent").orElseThrow(() -> new FileFormatException(source, j.line(), at + ": expected a <parent link=\"...\"/>"));
      XmlTree.Element child = j.child("child").orElseThrow(() -> new FileFormatException(source, j.line(), at + ": expected a <child link=\"...\"/>"));
      String p = linkRef(parent, at + " <parent>", links);
      String c = linkRef(child, at + " <child>", links);
      Transform X_PJ = origin(j, at);
      Vec3 axis = new Vec3(1, 0, 0);
      int axisLine = j.line();
      Optional<XmlTree.Element> ax = j.child("axis");
      if (ax.isPresent()) {
        double[] a = numbers(ax.get(), "xyz", at + " <axis>", 3, "the axis direction", null);
        axis = new Vec3(a[0], a[1], a[2]);
        axisLine = ax.get().line();
        if (type.equals("fixed")) {
          axis = new Vec3(1, 0, 0);
        } else if (axis.norm() < 1e-9) {
          throw new FileFormatException(source, axisLine, at + " <axis xyz>: expected a non-zero direction, got 0 0 0");
        }
      }
      Optional<Limit> limit = Optional.empty();
      Optional<XmlTree.Element> le = j.child("limit");
      if (le.isPresent() && !type.equals("fixed")) {
        XmlTree.Element l = le.get();
        double toInternal = type.equals("prismatic") ? 1000 : 1;
        boolean hasLower = l.attribute("lower").isPresent();
        boolean hasUpper = l.attribute("upper").isPresent();
        double lower = hasLower ? number(l, "lower", at + " <limit>", type.equals("prismatic") ? "metres" : "radians") * toInternal : 0;
        double upper = hasUpper ? number(l, "upper", at + " <limit>", type.equals("prismatic") ? "metres" : "radians") * toInternal : 0;
        double velocity = l.attribute("velocity").isPresent()
            ? number(l, "velocity", at + " <limit>", type.equals("prismatic") ? "m/s" : "rad/s") * toInternal : Double.NaN;
        limit = Optional.of(new Limit(l.line(), lower, upper, velocity, hasLower, hasUpper));
      }
      return new Joint(name, type, j.line(), p, parent.line(), c, child.line(), X_PJ, axis, axisLine, limit,
          j.child("mimic").isPresent());
    }

    private String linkRef(XmlTree.Element e, String at, Map<String, Link> links) {
      String l = e.attribute("link").orElse("").strip();
      if (l.isEmpty()) {
        throw new FileFormatException(source, e.line(), at + ": expected a link attribute");
      }
      if (!links.containsKey(l)) {
        throw new FileFormatException(source, e.line(), at + ": unknown link '" + l + "': expected one of the file's links "
            + preview(links.keySet()));
      }
      return l;
    }

    Geometry geometry(XmlTree.Element e, String at, Map<String, String> materials) {
      Transform X_LG = origin(e, at);
      XmlTree.Element g = e.child("geometry").orElseThrow(() -> new FileFormatException(source, e.line(), at + ": expected a <geometry>"));
      if (g.children().isEmpty()) {
        throw new FileFormatException(source, g.line(), at + " <geometry>: expected a box, cylinder, sphere or mesh");
      }
      XmlTree.Element s = g.children().get(0);
      String sat = at + " <" + s.name() + ">";
      Shape shape = switch (s.name()) {
        case "box" -> {
          double[] size = numbers(s, "size", sat, 3, "metres", null);
          positive(s, sat + " size", size);
          yield new Shape.Box(new Vec3(size[0] * 1000, size[1] * 1000, size[2] * 1000));
        }
        case "cylinder" -> {
          double r = number(s, "radius", sat, "metres");
          double l = number(s, "length", sat, "metres");
          positive(s, sat + " radius and length", new double[] {r, l});
          yield new Shape.Cylinder(r * 1000, l * 1000);
        }
        case "sphere" -> {
          double r = number(s, "radius", sat, "metres");
          positive(s, sat + " radius", new double[] {r});
          yield new Shape.Sphere(r * 1000);
        }
        case "mesh" -> {
          String f = s.attribute("filename").orElse("").strip();
          if (f.isEmpty()) {
            throw new FileFormatException(source, s.line(), sat + ": expected a filename attribute");
          }
          double[] scale = numbers(s, "scale", sat, 3, "scale factors", new double[] {1, 1, 1});
          for (double k : scale) {
            if (k == 0) {
              throw new FileFormatException(source, s.line(), sat + " scale: expected non-zero factors, got 0");
            }
          }
          yield new Shape.Mesh(f, new Vec3(scale[0], scale[1], scale[2]));
        }
        default -> throw new FileFormatException(source, s.line(), sat + ": expected a box, cylinder, sphere or mesh");
      };
      Optional<String> color = Optional.empty();
      Optional<XmlTree.Element> m = e.child("material");
      if (m.isPresent()) {
        color = materialColor(m.get());
        if (color.isEmpty()) {
          color = Optional.ofNullable(materials.get(m.get().attribute("name").orElse("")));
        }
      }
      return new Geometry(s.line(), X_LG, shape, color);
    }

    Optional<String> materialColor(XmlTree.Element m) {
      Optional<XmlTree.Element> c = m.child("color");
      if (c.isEmpty()) {
        return Optional.empty();
      }
      double[] rgba = numbers(c.get(), "rgba", "<material> <color>", 4, "numbers 0..1", null);
      int r = (int) Math.round(Math.clamp(rgba[0], 0, 1) * 255);
      int g = (int) Math.round(Math.clamp(rgba[1], 0, 1) * 255);
      int b = (int) Math.round(Math.clamp(rgba[2], 0, 1) * 255);
      return Optional.of(String.format(Locale.ROOT, "#%02x%02x%02x", r, g, b));
    }

    /** {@code <origin xyz rpy>} of {@code e} (metres, radians) as a transform in mm; identity when absent. */
    Transform origin(XmlTree.Element e, String at) {
      Optional<XmlTree.Element> o = e.child("origin");
      if (o.isEmpty()) {
        return Transform.IDENTITY;
      }
      double[] xyz = numbers(o.get(), "xyz", at + " <origin>", 3, "metres", new double[3]);
      double[] rpy = numbers(o.get(), "rpy", at + " <origin>", 3, "radians", new double[3]);
      return Transform.fromRpy(xyz[0] * 1000, xyz[1] * 1000, xyz[2] * 1000, rpy[0], rpy[1], rpy[2]);
    }

    double number(XmlTree.Element e, String attr, String at, String unit) {
      String text = e.attribute(attr).orElseThrow(() ->
          new FileFormatException(source, e.line(), at + ": expected a " + attr + " attribute (" + unit + ")"));
      double[] d = parseNumbers(text.strip(), 1);
      if (d == null) {
        throw new FileFormatException(source, e.line(), at + " " + attr + ": expected a number (" + unit + "), got \"" + text + "\"");
      }
      return d[0];
    }

    double[] numbers(XmlTree.Element e, String attr, String at, int count, String unit, double[] fallback) {
      Optional<String> text = e.attribute(attr);
      if (text.isEmpty()) {
        if (fallback != null) {
          return fallback;
        }
        throw new FileFormatException(source, e.line(), at + ": expected a " + attr + " attribute (" + count + " " + unit + ")");
      }
      double[] d = parseNumbers(text.get().strip(), count);
      if (d == null) {
        throw new FileFormatException(source, e.line(), at + " " + attr + ": expected " + count + " numbers (" + unit
            + ") separated by spaces, got \"" + text.get() + "\"");
      }
      return d;
    }

    private void positive(XmlTree.Element e, String at, double[] values) {
      for (double d : values) {
        if (!(d > 0)) {
          throw new FileFormatException(source, e.line(), at + ": expected positive sizes, got " + d);
        }
      }
    }

    private static double[] parseNumbers(String text, int count) {
      String[] parts = text.isEmpty() ? new String[0] : text.split("\\s+");
      if (parts.length != count) {
        return null;
      }
      double[] out = new double[count];
      for (int i = 0; i < count; i++) {
        try {
          out[i] = Double.parseDouble(parts[i]);
        } catch (NumberFormatException ex) {
          return null;
        }
        // Java also reads "NaN", "Infinity" and "1d": none is a URDF number.
        if (!Double.isFinite(out[i]) || !parts[i].matches("[-+]?(\\d+\\.?\\d*|\\.\\d+)([eE][-+]?\\d+)?")) {
          return null;
        }
      }
      return out;
    }

    private static String preview(java.util.Collection<String> names) {
      List<String> l = new ArrayList<>(names);
      return l.size() <= 8 ? l.toString() : l.subList(0, 8) + " and " + (l.size() - 8) + " more";
    }
  }
}
