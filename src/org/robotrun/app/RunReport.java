package org.robotrun.app;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import org.robotrun.math.Xyzwpr;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.IoKind;
import org.robotrun.program.Position;
import org.robotrun.program.Registers;
import org.robotrun.sim.Controller;
import org.robotrun.sim.ControllerAlarm;
import org.robotrun.sim.HeadlessRun;
import org.robotrun.sim.MotionTiming;
import org.robotrun.sim.CollisionEvent;
import org.robotrun.sim.Simulation;
import org.robotrun.world.ObjectKind;
import org.robotrun.world.World;
import org.robotrun.world.WorldObject;

/** The JSON report of {@code robotrun run}; the schema is documented in docs/run-report.md. */
final class RunReport {
  private static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

  private RunReport() {}

  /** The report as UTF-8 JSON bytes. */
  static byte[] bytes(HeadlessRun.CellResult result, Simulation sim) throws IOException {
    return JSON.writeValueAsBytes(build(result, sim));
  }

  /**
   * The top level describes the cell (for one robot, that robot's run, as before several robots
   * existed): {@code status} is "finished" when every robot finished, {@code alarm} the alarm
   * that ended the run, {@code program} the first running robot's program, {@code cycleTimeSec}
   * the cell's cycle time. Each entry of {@code robots} has its own program, status, alarm,
   * cycle and busy time besides its state.
   */
  static ObjectNode build(HeadlessRun.CellResult result, Simulation sim) {
    ObjectNode root = JSON.createObjectNode();
    root.put("status", result.status() == HeadlessRun.Status.FINISHED ? "finished" : "alarm");
    alarm(root, result.alarm());
    root.put("program", result.robots().get(0).program());
    root.put("simTimeSec", round(result.simTimeSec(), 6));
    root.put("cycleTimeSec", round(result.cycleTimeSec(), 6));
    ArrayNode robots = root.putArray("robots");
    for (Controller c : sim.controllers()) {
      ObjectNode r = robots.addObject();
      r.put("name", c.name());
      HeadlessRun.RobotResult rr = result.robots().stream().filter(x -> x.robot().equals(c.name())).findFirst().orElse(null);
      if (rr == null) {
        r.putNull("program");
        // No program of its own: its controller's alarm (another robot ran into it), if any.
        r.put("status", c.hasActiveAlarm() ? "alarm" : "idle");
        alarm(r, c.activeAlarms().stream().findFirst());
      } else {
        r.put("program", rr.program());
        r.put("status", rr.status().name().toLowerCase(java.util.Locale.ROOT));
        alarm(r, rr.alarm());
        r.put("cycleTimeSec", round(rr.cycleTimeSec(), 6));
        r.put("busyTimeSec", round(rr.busyTimeSec(), 6));
      }
      robot(r, c);
    }
    ArrayNode parts = root.putArray("parts");
    World world = sim.world();
    java.util.Map<String, String> held = sim.heldParts();
    for (WorldObject o : world.objects()) {
      if (o.kind() != ObjectKind.PART) {
        continue;
      }
      ObjectNode part = parts.addObject();
      part.put("name", o.name());
      // what the part became (a vision cell may draw its kind): shape, colour and the vision models it matches
      part.put("shape", org.robotrun.world.VisionSetup.Model.shapeKind(o.shape()));
      part.put("colour", o.colour().hex());
      ArrayNode models = part.putArray("models");
      sim.vision().ifPresent(v -> v.setup().models().stream().filter(m -> m.matches(o))
          .forEach(m -> models.add(m.name())));
      Xyzwpr p = Xyzwpr.fromTransform(world.poseInCell(o.name()));
      ObjectNode pose = part.putObject("pose_cell");
      pose.put("x", round(p.x(), 4));
      pose.put("y", round(p.y(), 4));
      pose.put("z", round(p.z(), 4));
      pose.put("w", round(p.wDeg(), 4));
      pose.put("p", round(p.pDeg(), 4));
      pose.put("r", round(p.rDeg(), 4));
      if (o.parent().isPresent()) {
        part.put("parent", o.parent().get());
      } else {
        part.putNull("parent");
      }
      String holder = held.get(o.name());
      if (holder != null) {
        part.put("heldBy", holder);
      } else {
        part.putNull("heldBy");
      }
    }
    ArrayNode collisions = root.putArray("collisions");
    for (CollisionEvent e : sim.collisionEvents()) {
      ObjectNode o = collisions.addObject();
      o.put("timeSec", round(e.simTimeSec(), 6));
      o.put("a", e.bodyA());
      o.put("b", e.bodyB());
      o.put("aName", e.nameA());
      o.put("bName", e.nameB());
    }
    // WARN alarms (a refused RUN or PLC start): raised, shown, and every program went on
    ArrayNode warnings = root.putArray("warnings");
    for (Controller c : sim.controllers()) {
      for (ControllerAlarm a : c.warnings()) {
        ObjectNode o = warnings.addObject();
        o.put("robot", c.name());
        o.put("timeSec", round(a.simTimeSec(), 6));
        o.put("code", a.code());
        o.put("message", a.message());
        o.put("program", a.program());
        o.put("line", a.line());
      }
    }
    return root;
  }

  private static void alarm(ObjectNode o, java.util.Optional<ControllerAlarm> alarm) {
    if (alarm.isPresent()) {
      ControllerAlarm a = alarm.get();
      ObjectNode al = o.putObject("alarm");
      al.put("code", a.code());
      al.put("message", a.message());
      al.put("program", a.program());
      al.put("line", a.line());
    } else {
      o.putNull("alarm");
    }
  }

  private static void robot(ObjectNode r, Controller c) {
    ArrayNode joints = r.putArray("joints_deg");
    Position.Joint j = c.currentJoints();
    for (int i = 1; i <= 6; i++) {
      joints.add(round(j.element(i), 6));
    }
    Xyzwpr t = c.tcpInWorld();
    ObjectNode tcp = r.putObject("tcp_world");
    tcp.put("x", round(t.x(), 4));
    tcp.put("y", round(t.y(), 4));
    tcp.put("z", round(t.z(), 4));
    tcp.put("w", round(t.wDeg(), 4));
    tcp.put("p", round(t.pDeg(), 4));
    tcp.put("r", round(t.rDeg(), 4));
    r.put("utool", c.frames().active(FrameKind.TOOL));
    r.put("uframe", c.frames().active(FrameKind.USER));
    r.put("overridePct", c.overridePct());
    Registers regs = c.registers();
    ObjectNode registers = r.putObject("registers");
    ObjectNode rr = registers.putObject("R");
    for (int i = 1; i <= Registers.R_COUNT; i++) {
      if (regs.number(i) != 0 || !regs.isInteger(i)) {
        if (regs.isInteger(i)) {
          rr.put(Integer.toString(i), (long) regs.number(i));
        } else {
          rr.put(Integer.toString(i), finite(regs.number(i)));
        }
      }
    }
    ObjectNode pr = registers.putObject("PR");
    for (int i = 1; i <= Registers.PR_COUNT; i++) {
      Position p = regs.position(i);
      if (!p.equals(Position.Cartesian.ZERO)) {
        pr.set(Integer.toString(i), position(p));
      }
    }
    ObjectNode io = r.putObject("io");
    for (IoKind k : IoKind.values()) {
      ObjectNode ports = io.putObject(k.name());
      for (int i = 1; i <= regs.ioSize(k); i++) {
        int v = regs.value(k, i);
        if (v != 0) {
          if (k.group()) {
            ports.put(Integer.toString(i), v);
          } else {
            ports.put(Integer.toString(i), true);
          }
        }
      }
    }
    ArrayNode motions = r.putArray("motions");
    for (MotionTiming m : c.motionTimings()) {
      ObjectNode o = motions.addObject();
      o.put("program", m.program());
      o.put("line", m.line());
      o.put("startSec", round(m.startSec(), 6));
      o.put("durationSec", round(m.durationSec(), 6));
    }
  }

  private static ObjectNode position(Position p) {
    ObjectNode o = JSON.createObjectNode();
    switch (p) {
      case Position.Cartesian c -> {
        o.put("x", finite(c.xMm()));
        o.put("y", finite(c.yMm()));
        o.put("z", finite(c.zMm()));
        o.put("w", finite(c.wDeg()));
        o.put("p", finite(c.pDeg()));
        o.put("r", finite(c.rDeg()));
        var cf = c.config();
        o.put("config", (cf.flip() ? "F" : "N") + " " + (cf.up() ? "U" : "D") + " " + (cf.top() ? "T" : "B")
            + ", " + cf.turn1() + ", " + cf.turn2() + ", " + cf.turn3());
      }
      case Position.Joint j -> {
        ArrayNode a = o.putArray("joints_deg");
        for (int i = 1; i <= 6; i++) {
          a.add(finite(j.element(i)));
        }
      }
    }
    return o;
  }

  /**
   * {@code v}, which the schema says is a JSON number: Jackson would write NaN and infinities as
   * strings. Arithmetic overflow is an alarm in the interpreter, so none can reach here; if one
   * did, the report is refused rather than written against its schema.
   */
  private static double finite(double v) {
    if (!Double.isFinite(v)) {
      throw new IllegalStateException("a non-finite number reached the run report: " + v);
    }
    return v;
  }

  private static double round(double v, int decimals) {
    finite(v);
    double s = Math.pow(10, decimals);
    double r = Math.round(v * s) / s;
    return r == 0 ? 0 : r;
  }
}
