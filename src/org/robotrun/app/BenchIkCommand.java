package org.robotrun.app;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.robotrun.io.FileFormatException;
import org.robotrun.io.IkTargetsCsv;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.math.Angles;
import org.robotrun.math.Transform;
import org.robotrun.robot.ClosedFormIk;
import org.robotrun.robot.Config;
import org.robotrun.robot.ForwardKinematics;
import org.robotrun.robot.IkResult;
import org.robotrun.robot.KinematicChain;
import org.robotrun.robot.NumericIk;
import org.robotrun.robot.ResolvedRate;
import org.robotrun.robot.RobotModel;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/** {@code robotrun bench ik}: solves every row of a reference target file and prints one line. */
@Command(
    name = "ik",
    mixinStandardHelpOptions = true,
    description = {
      "Solve every target of a reference IK file with the default robot and print one summary line.",
      "The file has the columns id, q1..q6, x, y, z (m), r11..r33, s1..s6, n1..n6 (see docs/kinematics.md):",
      "  solved=N/M in_limits=N/M same_config=N/M median_us=X p99_us=Y",
      "solved: FK of the answer within 0.1 mm and 0.01 rad of the target;",
      "same_config: joints equal the ground truth within 1e-6 rad (wrapped).",
      "Times: System.nanoTime around each solve only, in the last of several",
      "passes (see --warmup, --warmup-ms).",
      "closed-form picks the branch by the CONFIG of the row's ground truth;",
      "numeric starts from --start. resolved-rate times one step per target",
      "(ground-truth joints; 100 mm/s along X, 0.2 rad/s about Z) and prints",
      "  steps=M damped=K median_us=X p99_us=Y",
      ""
    })
public final class BenchIkCommand implements Callable<Integer> {

  @Spec CommandSpec spec;

  @Option(names = "--targets", required = true, paramLabel = "FILE",
      description = "Reference targets CSV (id, q1..q6, x, y, z in m, r11..r33, s1..s6, n1..n6).")
  Path targets;

  @Option(names = "--start", defaultValue = "home", paramLabel = "home|random|near",
      description = "Numeric solver start: home (q = 0), random (s1..s6) or near (n1..n6). Default: ${DEFAULT-VALUE}.")
  String start;

  @Option(names = "--solver", defaultValue = "closed-form", paramLabel = "closed-form|numeric|resolved-rate",
      description = "Solver to measure. Default: ${DEFAULT-VALUE}.")
  String solver;

  @Option(names = "--out", paramLabel = "FILE",
      description = "Write one row per target: id,q1..q6 (rad), empty fields where the solve failed.")
  Path out;

  @Option(names = "--warmup", defaultValue = "20", paramLabel = "N",
      description = "At least N untimed passes over the targets before the timed one. Default: ${DEFAULT-VALUE}.")
  int warmup;

  @Option(names = "--warmup-ms", defaultValue = "2000", paramLabel = "MS",
      description = "And for at least MS ms, so the JIT is done even on a busy machine. Default: ${DEFAULT-VALUE}.")
  long warmupMs;

  @Override
  public Integer call() {
    if (!List.of("home", "random", "near").contains(start)) {
      throw new ParameterException(spec.commandLine(), "--start: expected home, random or near, got '" + start + "'");
    }
    if (!List.of("closed-form", "numeric", "resolved-rate").contains(solver)) {
      throw new ParameterException(spec.commandLine(),
          "--solver: expected closed-form, numeric or resolved-rate, got '" + solver + "'");
    }
    if (warmup < 0) {
      throw new ParameterException(spec.commandLine(), "--warmup: expected a count >= 0, got " + warmup);
    }
    if (warmupMs < 0) {
      throw new ParameterException(spec.commandLine(), "--warmup-ms: expected a duration >= 0, got " + warmupMs);
    }
    List<IkTargetsCsv.Target> rows = read(targets);
    RobotModel robot = RobotDefinitions.defaultRobot();
    PrintWriter o = spec.commandLine().getOut();
    if (solver.equals("resolved-rate")) {
      o.println(resolvedRate(robot, rows));
    } else {
      o.println(ik(robot, rows));
    }
    o.flush();
    return Main.EXIT_OK;
  }

  private String ik(RobotModel robot, List<IkTargetsCsv.Target> rows) {
    int m = rows.size();
    Transform[] poses = new Transform[m];
    Config[] configs = new Config[m];
    double[][] starts = new double[m][];
    ClosedFormIk closed = robot.opw().isPresent() ? new ClosedFormIk(robot) : null;
    if (solver.equals("closed-form") && closed == null) {
      throw new UserError(robot.id() + " has no OPW parameters: use --solver numeric", Main.EXIT_FAILED);
    }
    NumericIk numeric = new NumericIk(robot);
    for (int i = 0; i < m; i++) {
      IkTargetsCsv.Target t = rows.get(i);
      poses[i] = t.X_BF();
      configs[i] = closed == null ? null : closed.configOf(t.q());
      starts[i] = switch (start) {
        case "random" -> t.randomStart();
        case "near" -> t.nearStart();
        default -> new double[6];
      };
    }
    boolean useClosed = solver.equals("closed-form");
    IkResult[] results = new IkResult[m];
    long[] nanos = new long[m];
    long warmupEnd = System.nanoTime() + warmupMs * 1_000_000;
    for (int pass = 0; pass <= warmup || System.nanoTime() < warmupEnd; pass++) {
      for (int i = 0; i < m; i++) {
        long t0 = System.nanoTime();
        IkResult r = useClosed ? closed.solve(poses[i], configs[i]) : numeric.solve(poses[i], starts[i]);
        long t1 = System.nanoTime();
        results[i] = r;
        nanos[i] = t1 - t0;
      }
    }
    int solved = 0, inLimits = 0, sameConfig = 0;
    double[][] solutions = new double[m][];
    for (int i = 0; i < m; i++) {
      if (!(results[i] instanceof IkResult.Solved s)) {
        continue;
      }
      // Judge with the reference FK, not the solver's own residuals.
      Transform reached = ForwardKinematics.flangePoseInBase(robot, s.q());
      if (reached.distanceTo(poses[i]) < 0.1 && reached.rotationAngleTo(poses[i]) < 0.01) {
        solved++;
        solutions[i] = s.q();
        if (robot.firstJointOutsideLimits(s.q()) < 0) {
          inLimits++;
        }
        if (sameJoints(s.q(), rows.get(i).q())) {
          sameConfig++;
        }
      }
    }
    if (out != null) {
      writeSolutions(rows, solutions);
    }
    return String.format(Locale.ROOT, "solved=%d/%d in_limits=%d/%d same_config=%d/%d median_us=%.3f p99_us=%.3f",
        solved, m, inLimits, m, sameConfig, m, percentileMicros(nanos, 50), percentileMicros(nanos, 99));
  }

  private String resolvedRate(RobotModel robot, List<IkTargetsCsv.Target> rows) {
    int m = rows.size();
    ResolvedRate rr = new ResolvedRate(new KinematicChain(robot), ResolvedRate.Settings.defaults());
    double[] twist = {100, 0, 0, 0, 0, 0.2};
    double[] qDot = new double[6];
    long[] nanos = new long[m];
    int damped = 0;
    long warmupEnd = System.nanoTime() + warmupMs * 1_000_000;
    for (int pass = 0; pass <= warmup || System.nanoTime() < warmupEnd; pass++) {
      damped = 0;
      for (int i = 0; i < m; i++) {
        double[] q = rows.get(i).q();
        long t0 = System.nanoTime();
        rr.step(q, twist, null, qDot);
        long t1 = System.nanoTime();
        nanos[i] = t1 - t0;
        if (rr.lastDamping() > 0) {
          damped++;
        }
      }
    }
    return String.format(Locale.ROOT, "steps=%d damped=%d median_us=%.3f p99_us=%.3f",
        m, damped, percentileMicros(nanos, 50), percentileMicros(nanos, 99));
  }

  private static boolean sameJoints(double[] q, double[] truth) {
    for (int i = 0; i < 6; i++) {
      if (Math.abs(Angles.wrapPi(q[i] - truth[i])) > 1e-6) {
        return false;
      }
    }
    return true;
  }

  /** Nearest-rank percentile (µs). */
  private static double percentileMicros(long[] nanos, int pct) {
    long[] sorted = nanos.clone();
    Arrays.sort(sorted);
    int rank = (int) Math.ceil(pct / 100.0 * sorted.length);
    return sorted[Math.max(0, rank - 1)] / 1000.0;
  }

  private static List<IkTargetsCsv.Target> read(Path file) {
    try {
      List<IkTargetsCsv.Target> rows = IkTargetsCsv.read(file);
      if (rows.isEmpty()) {
        throw new UserError(file + ": no targets (only a header)");
      }
      return rows;
    } catch (NoSuchFileException e) {
      throw new UserError(file + ": no such file");
    } catch (org.robotrun.io.UnreadableFileException e) {
      throw new UserError(file + ": " + e.getMessage());
    } catch (IOException e) {
      throw new UserError(file + ": cannot read: " + e.getMessage());
    } catch (FileFormatException e) {
      throw new UserError(e.getMessage());
    }
  }

  private void writeSolutions(List<IkTargetsCsv.Target> rows, double[][] solutions) {
    StringBuilder sb = new StringBuilder("id,q1,q2,q3,q4,q5,q6\n");
    for (int i = 0; i < rows.size(); i++) {
      sb.append(rows.get(i).id());
      for (int j = 0; j < 6; j++) {
        sb.append(',');
        if (solutions[i] != null) {
          sb.append(solutions[i][j]);
        }
      }
      sb.append('\n');
    }
    try {
      org.robotrun.io.AtomicFiles.write(out, sb.toString().getBytes(java.nio.charset.StandardCharsets.UTF_8));
    } catch (IOException e) {
      throw new UserError(out + ": cannot write: " + e.getMessage());
    }
  }
}
