package org.robotrun.sim;

import java.util.List;
import org.robotrun.math.Xyzwpr;

/**
 * One robot's state at an instant, immutable (for the GUI's status panels and reports).
 *
 * @param name robot name
 * @param jointsDeg J1..J6 as the pendant shows them (deg, coupled J3)
 * @param tcpWorld TCP of the active tool in WORLD (mm, rad; {@link Xyzwpr#wDeg()} for degrees)
 * @param utool active tool frame number
 * @param uframe active user frame number
 * @param overridePct speed override
 * @param status program execution
 * @param activeAlarms alarms not yet reset
 */
public record RobotState(String name, double[] jointsDeg, Xyzwpr tcpWorld, int utool, int uframe, int overridePct,
    ExecutionStatus status, List<ControllerAlarm> activeAlarms) {
  public RobotState {
    jointsDeg = jointsDeg.clone();
    activeAlarms = List.copyOf(activeAlarms);
  }

  @Override
  public double[] jointsDeg() {
    return jointsDeg.clone();
  }
}
