package org.robotrun.grade;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.robotrun.program.Registers;
import org.robotrun.sim.CollisionEvent;
import org.robotrun.sim.ControllerAlarm;
import org.robotrun.sim.FrameTable;
import org.robotrun.sim.HeadlessRun;
import org.robotrun.sim.SceneSnapshot;
import org.robotrun.world.World;

/**
 * How one simulated run of a submission ended; the checks read it.
 *
 * @param label "nominal" or "variation 3 (override 80%)", for messages
 * @param finished the program reached its end with the arm at rest
 * @param alarm the alarm that stopped it (time limit: RUN-001)
 * @param cycleTimeSec simulated seconds from start to end
 * @param world the parts and fixtures at the end
 * @param heldParts part name to the robot holding it
 * @param collisions contacts that began during the run
 * @param registers the first robot's registers and I/O at the end
 * @param frames the first robot's frame table at the end
 * @param scene the final state as a draw list, for the report's pictures
 * @param startParents each part's parent at the start, to tell a moved part
 * @param robots every robot of the cell, in scenario order
 * @param tcpPath the first robot's active TCP in WORLD at every tick, for {@link Check.TcpVisits}
 * @param warnings the WARN alarms of every robot (a refused RUN or PLC start), oldest first per robot
 */
public record RunOutcome(String label, boolean finished, Optional<ControllerAlarm> alarm, double cycleTimeSec,
    World world, Map<String, String> heldParts, List<CollisionEvent> collisions, Registers registers,
    FrameTable frames, SceneSnapshot scene, Map<String, Optional<String>> startParents, List<RobotOutcome> robots,
    List<org.robotrun.math.Vec3> tcpPath, List<ControllerAlarm> warnings) {

  /** The robot a check looks at: by name, or the first robot when none is named. */
  public RobotOutcome robot(Optional<String> name) {
    return name.flatMap(n -> robots.stream().filter(r -> r.robot().equals(n)).findFirst()).orElse(robots.get(0));
  }

  /**
   * How one robot's program ended.
   *
   * @param program what it ran ("" when it had nothing to run)
   * @param status empty when it had nothing to run
   * @param alarm its own alarm (a time limit is every running robot's)
   * @param cycleTimeSec from the common start to its end
   * @param registers its registers and I/O at the end
   * @param frames its frame table at the end
   */
  public record RobotOutcome(String robot, String program, Optional<HeadlessRun.RobotStatus> status,
      Optional<ControllerAlarm> alarm, double cycleTimeSec, Registers registers, FrameTable frames) {
    public boolean finished() {
      return status.equals(Optional.of(HeadlessRun.RobotStatus.FINISHED));
    }
  }
}
