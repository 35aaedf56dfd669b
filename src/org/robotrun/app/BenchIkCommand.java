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
import org.robotrun.math.Transform;
import org.robotrun.robot.IkSolver;
import org.robotrun.robot.OffsetWristIk;
import org.robotrun.robot.Config;
import org.robotrun.robot.ForwardKinematics;
import org.robotrun.robot.IkResult;
import org.robotrun.robot.KinematicChain;
import org.robotrun.robot.NumericIk;
import org.robotrun.robot.ResolvedRate;
import org.robotrun.robot.RobotModel;
import org.robotrun.robot.UrTypeIk;
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
      "Solve every target of an IK target file with a robot and print one summary line.",
      "The robot is --robot (default lrmate200id). The file has the columns id, q1..q6, x, y, z (m, robot base frame), r11..r33, s1..s6, n1..n6 (see docs/kinematics.md); --generate N makes N targets instead, from FK of random joint vectors inside the limits (--seed), optionally saved (--write-targets):",
      "  solved=N/M in_limits=N/M same_config=N/M median_us=X p99_us=Y robot=ID solver=KIND",
      "solved: FK of the answer within 0.1 mm and 0.01 rad of the target;",
      "same_config: the answer's CONFIG (flags and turn numbers) equals the ground truth's.",
      "Times: System.nanoTime around each solve only, in the last of several passes (see --warmup, --warmup-ms).",
      "The robot's own solver (--solver auto: closed-form where the chain is OPW, offset-wrist for the CRX layout, ur-type for three parallel axes with an offset wrist, else numeric) and closed-form/offset-wrist/ur-type pick the branch by the CONFIG of the row's ground truth; numeric starts from --start. resolved-rate times one step per target (ground-truth joints; 100 mm/s along X, 0.2 rad/s about Z) and prints:",
      "  steps=M damped=K median_us=X p99_us=Y",
      ""
    })
public final class BenchIkCommand implements Callable<Integer> {

  @Spec CommandSpec spec;

  @Option(names = "--targets", paramLabel = "FILE",
      description = "Targets CSV (id, q1..q6, x, y, z in m, r11..r33, s1..s6, n1..n6). Or --generate.")
  Path targets;

  @Option(names = "--robot", defaultValue = "lrmate200id", paramLabel = "ID|FILE",
      description = "Library id (see 'robotrun robots') or robot file. Default: ${DEFAULT-VALUE}.")
  String robotName;

  @Option(names = "--generate", paramLabel = "N",
      description = "Instead of --targets: N targets from FK of random joint vectors inside the robot's limits.")
  Integer generate;

  @Option(names = "--seed", defaultValue = "1", paramLabel = "S",
      description = "Seed of --generate. Default: ${DEFAULT-VALUE}.")
  long seed;

  @Option(names = "--write-targets", paramLabel = "FILE",
      description = "Write the generated targets (same CSV format as --targets).")
  Path writeTargets;

  @Option(names = "--start", defaultValue = "home", paramLabel = "home|random|near",
      description = "Numeric solver start: home (q = 0), random (s1..s6) or near (n1..n6). Default: ${DEFAULT-VALUE}.")
  String start;

  @Option(names = "--solver", defaultValue = "auto", paramLabel = "auto|closed-form|offset-wrist|ur-type|numeric|resolved-rate",
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
    if (!List.of("auto", "closed-form", "offset-wrist", "ur-type", "numeric", "resolved-rate").contains(solver)) {
      throw new ParameterException(spec.commandLine(),
          "--solver: expected auto, closed-form, offset-wrist, ur-type, numeric or resolved-rate, got '" + solver + "'");
    }
    if ((targets == null) == (generate == null)) {
      throw new ParameterException(spec.commandLine(), "give either --targets FILE or --generate N");
    }
    if (generate != null && (generate < 1 || generate > 1_000_000)) {
      throw new ParameterException(spec.commandLine(), "--generate: expected a count 1..1000000, got " + generate);
    }
    if (writeTargets != null && generate == null) {
      throw new ParameterException(spec.commandLine(), "--write-targets needs --generate");
    }
    if (warmup < 0) {
      throw new ParameterException(spec.commandLine(), "--warmup: expected a count >= 0, got " + warmup);
    }
    if (warmupMs < 0) {
      throw new ParameterException(spec.commandLine(), "--warmup-ms: expected a duration >= 0, got " + warmupMs);
    }
    RobotModel robot;
    try {
      robot = RobotDefinitions.resolve(robotName, null);
    } catch (FileFormatException e) {
      throw new UserError("--robot: " + e.getMessage());
    }
    List<IkTargetsCsv.Target> rows = targets != null ? read(targets) : generated(robot);
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
    IkSolver own = IkSolver.forModel(robot);
    String kind = solver.equals("auto") ? own.kind() : solver;
    IkSolver chosen = switch (kind) {
      case "closed-form" -> {
        if (robot.opw().isEmpty()) {
          throw new UserError(robot.id() + " is not an OPW arm (no closed form): use --solver auto or numeric", Main.EXIT_FAILED);
        }
        yield own;
      }
      case "offset-wrist" -> {
        if (!OffsetWristIk.applies(robot)) {
          throw new UserError(robot.id() + " does not have the CRX layout: use --solver auto or numeric", Main.EXIT_FAILED);
        }
        yield own;
      }
      case "ur-type" -> {
        if (!UrTypeIk.KIND.equals(own.kind())) {
          throw new UserError(robot.id() + " does not have three parallel axes with an offset wrist: use --solver auto or numeric",
              Main.EXIT_FAILED);
        }
        yield own;
      }
      default -> null;
    };
    NumericIk numeric = new NumericIk(robot);
    for (int i = 0; i < m; i++) {
      IkTargetsCsv.Target t = rows.get(i);
      poses[i] = t.X_BF();
      configs[i] = own.configOf(t.q());
      starts[i] = switch (start) {
        case "random" -> t.randomStart();
        case "near" -> t.nearStart();
        default -> new double[6];
      };
    }
    boolean useOwn = chosen != null;
    double[] home = new double[6];
    IkResult[] results = new IkResult[m];
    long[] nanos = new long[m];
    long warmupEnd = System.nanoTime() + warmupMs * 1_000_000;
    for (int pass = 0; pass <= warmup || System.nanoTime() < warmupEnd; pass++) {
      for (int i = 0; i < m; i++) {
        long t0 = System.nanoTime();
        IkResult r = useOwn ? chosen.solve(poses[i], configs[i], home) : numeric.solve(poses[i], starts[i]);
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
        if (own.configOf(s.q()).equals(configs[i])) {
          sameConfig++;
        }
      }
    }
    if (out != null) {
      writeSolutions(rows, solutions);
    }
    return String.format(Locale.ROOT, "solved=%d/%d in_limits=%d/%d same_config=%d/%d median_us=%.3f p99_us=%.3f robot=%s solver=%s",
        solved, m, inLimits, m, sameConfig, m, percentileMicros(nanos, 50), percentileMicros(nanos, 99), robot.id(), kind);
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

  /** Targets from FK of uniform random joint vectors inside the limits; starts as in the reference file. */
  private List<IkTargetsCsv.Target> generated(RobotModel robot) {
    java.util.Random rnd = new java.util.Random(seed);
    List<IkTargetsCsv.Target> out = new java.util.ArrayList<>();
    double[] lo = robot.lowerLimits(), hi = robot.upperLimits();
    for (int k = 0; k < generate; k++) {
      double[] q = new double[6], s = new double[6], n = new double[6];
      for (int i = 0; i < 6; i++) {
        q[i] = lo[i] + rnd.nextDouble() * (hi[i] - lo[i]);
      }
      for (int i = 0; i < 6; i++) {
        s[i] = lo[i] + rnd.nextDouble() * (hi[i] - lo[i]);
        n[i] = Math.max(lo[i], Math.min(hi[i], q[i] + (rnd.nextDouble() * 0.2 - 0.1)));
      }
      out.add(new IkTargetsCsv.Target(k, q, ForwardKinematics.flangePoseInBase(robot, q), s, n));
    }
    if (writeTargets != null) {
      try {
        IkTargetsCsv.write(writeTargets, out);
      } catch (IOException e) {
        throw new UserError(writeTargets + ": cannot write: " + e.getMessage());
      }
    }
    return out;
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
