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

  /** Saves {@code scenario} to {@code file}: a crash leaves either the old file or the new one. */
  public static void write(Scenario scenario, Path file) throws IOException {
    Path dir = file.toAbsolutePath().normalize().getParent();
    AtomicFiles.write(file, toJson(scenario, dir).getBytes(StandardCharsets.UTF_8));
  }

  /** The JSON text, with paths relative to {@code dir}. */
  public static String toJson(Scenario s, Path dir) throws IOException {
    StringWriter text = new StringWriter();
    DefaultPrettyPrinter pretty = new DefaultPrettyPrinter().withObjectIndenter(new DefaultIndenter("  ", "\n"));
    try (JsonGenerator g = new JsonFactory().createGenerator(text)) {
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
        g.writeStringField("model", r.modelId());
        pose(g, "basePose", r.X_CB());
        g.writeStringField("endEffector", r.endEffector().fileName());
        g.writeArrayFieldStart("jointsDeg");
        for (double q : r.initialJointsRad()) {
          g.writeNumber(Math.toDegrees(q));
        }
        g.writeEndArray();
        g.writeEndObject();
      }
      g.writeEndArray();
      g.writeArrayFieldStart("objects");
      for (WorldObject o : s.world().objects()) {
        object(g, o, dir);
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
          g.writeNumberField(e.getKey().toString(), e.getValue());
        }
        g.writeEndObject();
      }
      if (!s.toolFrames().isEmpty() || !s.userFrames().isEmpty()) {
        g.writeObjectFieldStart("frames");
        frameSet(g, "tool", s.toolFrames());
        frameSet(g, "user", s.userFrames());
        g.writeEndObject();
      }
      if (s.camera().isPresent()) {
        CameraView c = s.camera().get();
        g.writeObjectFieldStart("camera");
        g.writeObjectFieldStart("target");
        g.writeNumberField("x", c.targetMm().x());
        g.writeNumberField("y", c.targetMm().y());
        g.writeNumberField("z", c.targetMm().z());
        g.writeEndObject();
        g.writeNumberField("distance", c.distanceMm());
        g.writeNumberField("yawDeg", Math.toDegrees(c.yawRad()));
        g.writeNumberField("pitchDeg", Math.toDegrees(c.pitchRad()));
        g.writeEndObject();
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
        g.writeNumberField("x", b.lengthMm());
        g.writeNumberField("y", b.widthMm());
        g.writeNumberField("z", b.heightMm());
        g.writeEndObject();
      }
      case Shape.Cylinder c -> {
        g.writeStringField("shape", "cylinder");
        g.writeNumberField("radius", c.radiusMm());
        g.writeNumberField("height", c.heightMm());
      }
      case Shape.Mesh m -> {
        g.writeStringField("shape", "mesh");
        g.writeStringField("file", relative(dir, m.file()));
        g.writeNumberField("scale", m.scale());
      }
    }
    g.writeStringField("color", o.colour().hex());
    // A scenario stores where things start; a saved cell starts where its objects are now.
    pose(g, "pose", o.pose());
    if (o.parent().isPresent()) {
      g.writeStringField("parent", o.parent().get());
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
    g.writeNumberField("x", p.x());
    g.writeNumberField("y", p.y());
    g.writeNumberField("z", p.z());
    g.writeNumberField("w", p.wDeg());
    g.writeNumberField("p", p.pDeg());
    g.writeNumberField("r", p.rDeg());
    g.writeEndObject();
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
