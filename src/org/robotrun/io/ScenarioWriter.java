package org.robotrun.io;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.core.util.DefaultIndenter;
import com.fasterxml.jackson.core.util.DefaultPrettyPrinter;
import java.io.IOException;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Map;
import org.robotrun.math.Transform;
import org.robotrun.math.Xyzwpr;
import org.robotrun.world.CameraView;
import org.robotrun.world.RobotSetup;
import org.robotrun.world.Scenario;
import org.robotrun.world.Shape;
import org.robotrun.world.WorldObject;

/**
 * Writes scenarios in format 1 (what {@link ScenarioReader} reads), atomically. Mesh and
 * program paths are written relative to the new file's folder, with '/' separators.
 */
public final class ScenarioWriter {
  private ScenarioWriter() {}

  private static final JsonFactory JSON = new JsonFactory();

  /**
   * Saves {@code scenario} to {@code file}: a crash leaves either the old file or the new one.
   *
   * @throws IOException also when the text would be larger than {@link ScenarioReader} reads
   *     back (nothing is written then)
   */
  public static void write(Scenario scenario, Path file) throws IOException {
    Path dir = file.toAbsolutePath().normalize().getParent();
    AtomicFiles.write(file, readableBytes(toJson(scenario, dir), file));
  }

  /**
   * The UTF-8 bytes of {@code json} (scenario or {@code cell.json} text from {@link #toJson}) for
   * {@code file}, refused when {@link ScenarioReader} could not read them back: RobotRun never
   * writes a file it cannot open again.
   */
  public static byte[] readableBytes(String json, Path file) throws IOException {
    return readableBytes(json, file, ScenarioReader.MAX_FILE_BYTES);
  }

  static byte[] readableBytes(String json, Path file, long maxBytes) throws IOException {
    byte[] bytes = json.getBytes(StandardCharsets.UTF_8);
    if (bytes.length > maxBytes) {
      throw new TooLargeException(String.format(java.util.Locale.ROOT,
          "%s would be %.1f MiB, more than the %s RobotRun reads back; nothing was written. "
              + "Remove objects, or split the cell",
          file.getFileName(), bytes.length / 1048576.0, BoundedFiles.sizeText(maxBytes)));
    }
    return bytes;
  }

  /** A scenario text over the size RobotRun reads back: never written. */
  public static final class TooLargeException extends IOException {
    private static final long serialVersionUID = 1L;

    TooLargeException(String message) {
      super(message);
    }
  }

  /** The JSON text, with paths relative to {@code dir}. */
  public static String toJson(Scenario s, Path dir) throws IOException {
    return toJson(s, java.util.Optional.empty(), dir);
  }

  /**
   * The JSON text of a workspace's {@code cell.json}: the scenario (where things are now) and,
   * when given, the controller's {@code "state"} section.
   */
  public static String toJson(Scenario s, java.util.Optional<SavedState> state, Path dir) throws IOException {
    return toJson(s, state, dir, ScenarioReader.MAX_FILE_BYTES);
  }

  /**
   * The text indented for people; when that is over {@code maxBytes} (a cell of tens of
   * thousands of objects: indenting more than doubles the size), one object a line instead, so a
   * scenario that was read can be written back within the same limit.
   */
  static String toJson(Scenario s, java.util.Optional<SavedState> state, Path dir, long maxBytes) throws IOException {
    String pretty = toJson(s, state, dir, false);
    // A UTF-8 byte per char at least, at most three.
    if (pretty.length() <= maxBytes / 3 || pretty.getBytes(StandardCharsets.UTF_8).length <= maxBytes) {
      return pretty;
    }
    return toJson(s, state, dir, true);
  }

  private static String toJson(Scenario s, java.util.Optional<SavedState> state, Path dir, boolean compactObjects)
      throws IOException {
    StringWriter text = new StringWriter();
    DefaultPrettyPrinter pretty = new DefaultPrettyPrinter().withObjectIndenter(new DefaultIndenter("  ", "\n"));
    if (compactObjects) {
      // Array items start a line of their own, unindented (100 000 objects: 0.4 MB less).
      pretty = pretty.withArrayIndenter(new DefaultIndenter("", "\n"));
    }
    try (JsonGenerator g = JSON.createGenerator(text)) {
      g.setPrettyPrinter(pretty);
      g.writeStartObject();
      g.writeNumberField("format", ScenarioReader.FORMAT);
      if (!s.name().isEmpty()) {
        g.writeStringField("name", s.name());
      }
      if (!s.description().isEmpty()) {
        g.writeStringField("description", s.description());
      }
      g.writeArrayFieldStart("robots");
      for (RobotSetup r : s.robots()) {
        g.writeStartObject();
        g.writeStringField("name", r.name());
        // A robot file is kept as an absolute path once read; written relative, like meshes.
        g.writeStringField("model", RobotDefinitions.isPath(r.modelId()) && Path.of(r.modelId()).isAbsolute()
            ? relative(dir, Path.of(r.modelId())) : r.modelId());
        if (r.modelId().toLowerCase(java.util.Locale.ROOT).endsWith(".urdf") && Path.of(r.modelId()).isAbsolute()
            && !UrdfCache.packagesFor(Path.of(r.modelId())).isEmpty()) {
          g.writeObjectFieldStart("packages");
          for (Map.Entry<String, Path> p : new java.util.TreeMap<>(UrdfCache.packagesFor(Path.of(r.modelId()))).entrySet()) {
            g.writeStringField(p.getKey(), relative(dir, p.getValue()));
          }
          g.writeEndObject();
        }
        pose(g, "basePose", r.X_CB());
        g.writeStringField("endEffector", r.endEffector().fileName());
        g.writeArrayFieldStart("jointsDeg");
        for (double q : r.initialJointsRad()) {
          g.writeNumber(tidyText(Math.toDegrees(q)));
        }
        g.writeEndArray();
        if (!r.toolIo().equals(org.robotrun.world.ToolIo.DEFAULT)) {
          g.writeObjectFieldStart("toolIo");
          g.writeNumberField("output", r.toolIo().output());
          g.writeNumberField("actuated", r.toolIo().actuatedInput());
          g.writeNumberField("holding", r.toolIo().holdingInput());
          g.writeEndObject();
        }
        if (!r.io().isEmpty()) {
          g.writeObjectFieldStart("io");
          for (Map.Entry<String, Integer> e : r.io().entrySet()) {
            g.writeNumberField(e.getKey(), e.getValue());
          }
          g.writeEndObject();
        }
        if (!r.userAlarms().isEmpty()) {
          g.writeObjectFieldStart("userAlarms");
          for (Map.Entry<Integer, String> e : r.userAlarms().entrySet()) {
            g.writeStringField(Integer.toString(e.getKey()), e.getValue());
          }
          g.writeEndObject();
        }
        if (!r.programs().isEmpty()) {
          g.writeArrayFieldStart("programs");
          for (Path p : r.programs()) {
            g.writeString(relative(dir, p));
          }
          g.writeEndArray();
        }
        if (r.mainProgram().isPresent()) {
          g.writeStringField("mainProgram", r.mainProgram().get());
        }
        if (!r.macros().isEmpty()) {
          g.writeArrayFieldStart("macros");
          for (org.robotrun.world.RobotSetup.Macro m : r.macros()) {
            g.writeStartObject();
            g.writeStringField("name", m.name());
            g.writeStringField("program", m.program());
            g.writeEndObject();
          }
          g.writeEndArray();
        }
        if (!r.registers().isEmpty()) {
          g.writeObjectFieldStart("registers");
          for (Map.Entry<Integer, Double> e : r.registers().entrySet()) {
            number(g, e.getKey().toString(), e.getValue());
          }
          g.writeEndObject();
        }
        if (!r.toolFrames().isEmpty() || !r.userFrames().isEmpty()) {
          g.writeObjectFieldStart("frames");
          frameSet(g, "tool", r.toolFrames());
          frameSet(g, "user", r.userFrames());
          g.writeEndObject();
        }
        if (r.mode().isPresent()) {
          g.writeStringField("mode", r.mode().get());
        }
        g.writeEndObject();
      }
      g.writeEndArray();
      g.writeArrayFieldStart("objects");
      for (WorldObject o : s.world().objects()) {
        if (compactObjects) {
          StringWriter one = new StringWriter();
          try (JsonGenerator og = JSON.createGenerator(one)) {
            object(og, o, dir);
          }
          g.writeRawValue(one.toString());
        } else {
          object(g, o, dir);
        }
      }
      g.writeEndArray();
      if (!s.programs().isEmpty()) {
        g.writeArrayFieldStart("programs");
        for (Path p : s.programs()) {
          g.writeString(relative(dir, p));
        }
        g.writeEndArray();
      }
      if (s.mainProgram().isPresent()) {
        g.writeStringField("mainProgram", s.mainProgram().get());
      }
      if (!s.registers().isEmpty()) {
        g.writeObjectFieldStart("registers");
        for (Map.Entry<Integer, Double> e : s.registers().entrySet()) {
          number(g, e.getKey().toString(), e.getValue());
        }
        g.writeEndObject();
      }
      if (!s.toolFrames().isEmpty() || !s.userFrames().isEmpty()) {
        g.writeObjectFieldStart("frames");
        frameSet(g, "tool", s.toolFrames());
        frameSet(g, "user", s.userFrames());
        g.writeEndObject();
      }
      if (s.onCollision() != org.robotrun.world.CollisionResponse.ALARM) {
        g.writeStringField("onCollision", s.onCollision().fileName());
      }
      if (s.mode().isPresent()) {
        g.writeStringField("mode", s.mode().get());
      }
      WiringJson.write(g, s.wiring());
      if (s.camera().isPresent()) {
        CameraView c = s.camera().get();
        g.writeObjectFieldStart("camera");
        g.writeObjectFieldStart("target");
        number(g, "x", c.targetMm().x());
        number(g, "y", c.targetMm().y());
        number(g, "z", c.targetMm().z());
        g.writeEndObject();
        number(g, "distance", c.distanceMm());
        number(g, "yawDeg", Math.toDegrees(c.yawRad()));
        number(g, "pitchDeg", Math.toDegrees(c.pitchRad()));
        g.writeEndObject();
      }
      ProductionJson.write(g, s.production());
      VisionJson.write(g, s.vision(), ScenarioWriter::number);
      if (state.isPresent()) {
        StateJson.write(g, state.get());
      }
      g.writeEndObject();
    }
    return text + "\n";
  }

  private static void object(JsonGenerator g, WorldObject o, Path dir) throws IOException {
    g.writeStartObject();
    g.writeStringField("name", o.name());
    g.writeStringField("kind", switch (o.kind()) {
      case FIXTURE -> "fixture";
      case PART -> "part";
    });
    switch (o.shape()) {
      case Shape.Box b -> {
        g.writeStringField("shape", "box");
        g.writeObjectFieldStart("size");
        number(g, "x", b.lengthMm());
        number(g, "y", b.widthMm());
        number(g, "z", b.heightMm());
        g.writeEndObject();
      }
      case Shape.Cylinder c -> {
        g.writeStringField("shape", "cylinder");
        number(g, "radius", c.radiusMm());
        number(g, "height", c.heightMm());
      }
      case Shape.Mesh m -> {
        g.writeStringField("shape", "mesh");
        g.writeStringField("file", relative(dir, m.file()));
        number(g, "scale", m.scale());
      }
    }
    g.writeStringField("color", o.colour().hex());
    // A scenario stores where things start; a saved cell starts where its objects are now.
    pose(g, "pose", o.pose());
    if (o.parent().isPresent()) {
      g.writeStringField("parent", o.parent().get());
    }
    if (o.touchable()) {
      g.writeBooleanField("touchable", true);
    }
    g.writeEndObject();
  }

  private static void frameSet(JsonGenerator g, String name, Map<Integer, Transform> frames) throws IOException {
    if (frames.isEmpty()) {
      return;
    }
    g.writeObjectFieldStart(name);
    for (Map.Entry<Integer, Transform> e : frames.entrySet()) {
      pose(g, e.getKey().toString(), e.getValue());
    }
    g.writeEndObject();
  }

  private static void pose(JsonGenerator g, String field, Transform t) throws IOException {
    Xyzwpr p = Xyzwpr.fromTransform(t);
    g.writeObjectFieldStart(field);
    number(g, "x", p.x());
    number(g, "y", p.y());
    number(g, "z", p.z());
    number(g, "w", p.wDeg());
    number(g, "p", p.pDeg());
    number(g, "r", p.rDeg());
    g.writeEndObject();
  }

  /**
   * Writes a number rounded to 15 significant digits, and below 1e-12 as 0, so that 15° does
   * not come back as 14.999999999999998 after the trip through radians and a matrix; integral
   * values are written without a fraction.
   */
  private static void number(JsonGenerator g, String field, double v) throws IOException {
    g.writeFieldName(field);
    g.writeNumber(tidyText(v));
  }

  private static String tidyText(double v) {
    return org.robotrun.math.DecimalText.tidy(v);
  }

  private static String relative(Path dir, Path file) {
    Path abs = file.toAbsolutePath().normalize();
    // Different roots (another drive on Windows) cannot be made relative.
    if (dir.getRoot() == null || !dir.getRoot().equals(abs.getRoot())) {
      return abs.toString().replace('\\', '/');
    }
    return dir.relativize(abs).toString().replace('\\', '/');
  }
}
