package org.robotrun.grade;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.robotrun.program.Registers;
import org.robotrun.sim.CollisionEvent;
import org.robotrun.sim.ControllerAlarm;
import org.robotrun.sim.FrameTable;
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
 */
public record RunOutcome(String label, boolean finished, Optional<ControllerAlarm> alarm, double cycleTimeSec,
    World world, Map<String, String> heldParts, List<CollisionEvent> collisions, Registers registers,
    FrameTable frames, SceneSnapshot scene, Map<String, Optional<String>> startParents) {}
