package org.robotrun.app;

import java.io.PrintWriter;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.robot.IkSolver;
import org.robotrun.robot.RobotModel;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/** {@code robotrun robots}: the robot library, one line per model. */
@Command(
    name = "robots",
    mixinStandardHelpOptions = true,
    description = {
      "List the robot library: the ids a scenario's robot \"model\" may name.",
      "A scenario may give a path to a robot .json file instead. Columns: id, reach (mm, as the source states it), payload (kg), wrist (spherical: OPW closed form; offset: CRX layout; parallel: three parallel axes, UR layout; other), the IK solver chosen from the chain at load (closed-form, offset-wrist, ur-type, numeric), whether the pendant couples J3 to J2, and the model name. See docs/robots.md.",
      ""
    })
public final class RobotsCommand implements Callable<Integer> {
  @Spec CommandSpec spec;

  @Override
  public Integer call() {
    PrintWriter o = spec.commandLine().getOut();
    o.println(String.format(Locale.ROOT, "%-13s %8s %8s  %-9s  %-12s  %-10s  %s",
        "id", "reach_mm", "payload", "wrist", "solver", "coupled_j3", "name"));
    for (RobotDefinitions.Entry e : RobotDefinitions.library()) {
      RobotModel m = RobotDefinitions.load(e.id());
      o.println(String.format(Locale.ROOT, "%-13s %8s %8s  %-9s  %-12s  %-10s  %s",
          e.id(), number(e.reachMm(), "%.1f"), number(e.payloadKg(), "%.0f"), m.wristKind(), IkSolver.kindFor(m),
          m.coupledJ3() ? "yes" : "no", e.name()));
    }
    o.flush();
    return Main.EXIT_OK;
  }

  private static String number(double v, String format) {
    return Double.isNaN(v) ? "-" : String.format(Locale.ROOT, format, v);
  }
}
