package org.robotrun.app;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintWriter;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import org.robotrun.io.TerminalText;
import org.robotrun.program.Program;
import org.robotrun.world.Scenario;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code robotrun bench window}: the real window's frame rate, CPU and closing time. */
@Command(
    name = "window",
    mixinStandardHelpOptions = true,
    description = {
      "Open the real simulator window (needs a display: under Linux without one, 'xvfb-run -a -s \"-screen 0 1366x768x24\" "
          + "robotrun bench window') on a scenario, in a workspace of its own in a temporary folder, and measure it: "
          + "after 2 s of settling it stays idle, then jogs J1 back and forth from the pendant (TP ENABLE, DEADMAN, "
          + "SHIFT, +J1/-J1), then runs a program of the cell from the pendant (SELECT, SHIFT+FWD; started again "
          + "from line 1 on a reset scene when it ends), each for --seconds (the jog and the run after 1 s that is "
          + "not timed), then closes the window as its close button does.",
      "Output, one line per phase, then the close:",
      "  phase=idle|jog|run fps=F cpu_pct=P frame_cpu_ms=M frames=N seconds=S load=L",
      "  close_ms=C",
      "cpu_pct: the process's CPU time over the phase (every thread) in %% of one core. frame_cpu_ms: CPU time per "
          + "drawn frame of the window's thread and of Mesa's software rasteriser threads (llvmpipe, Linux), "
          + "less the time spent stepping the simulation; '-' when the phase drew no frame (an idle window draws "
          + "only when something needs a frame). load: the machine's 1-minute load average at the phase's end. close_ms: from the close "
          + "request to the end of the window's process, timed from this process, which starts the window in a "
          + "child JVM (extra JVM options for it in ROBOTRUN_BENCH_JAVA_OPTS, e.g. to profile it).",
      "CPU figures stay comparable on a loaded machine; fps does not (quote the load with them). "
          + "ROBOTRUN_BENCH_DETAIL=1 also prints, on stderr, each phase's CPU per frame of the window thread, Mesa's "
          + "threads and the simulation, the wall time per frame in each part of a frame, and the pixels drawn again per frame."
    })
public final class BenchWindowCommand implements Callable<Integer> {
  @Spec CommandSpec spec;

  @Option(names = "--width", defaultValue = "1366", description = "Window width (default: ${DEFAULT-VALUE}).")
  int width;

  @Option(names = "--height", defaultValue = "768", description = "Window height (default: ${DEFAULT-VALUE}).")
  int height;

  @Option(names = "--seconds", defaultValue = "5", description = "How long each phase is timed (default: ${DEFAULT-VALUE}).")
  double seconds;

  @Option(names = "--scenario", paramLabel = "FILE.json",
      description = "The cell (default: the shipped scenarios/pick-and-place.json).")
  Path scenario;

  @Option(names = "--program", paramLabel = "NAME",
      description = "The program the run phase runs (default: the scenario's first program).")
  String program;

  @Override
  public Integer call() throws IOException, InterruptedException {
    RenderCommand.checkSize("--width", width);
    RenderCommand.checkSize("--height", height);
    if (!(seconds > 0 && seconds <= 600)) {
      throw new UserError("--seconds: expected more than 0 and at most 600, got " + WallClock.format(seconds));
    }
    Path cell = scenario != null ? scenario : shippedScenario();
    List<String> names = programNames(cell);
    if (names.isEmpty()) {
      throw new UserError("--scenario: " + cell + " has no program for the run phase; give a scenario with one");
    }
    String prog = program == null ? names.get(0) : program.toUpperCase(Locale.ROOT);
    if (!names.contains(prog)) {
      throw new UserError("--program: " + cell + " has no program " + prog + " (it has " + String.join(", ", names) + ")");
    }
    Path tmp = Files.createTempDirectory("robotrun-bench-window");
    try {
      return runWindow(cell.toAbsolutePath(), prog, tmp);
    } finally {
      deleteTree(tmp);
    }
  }

  private int runWindow(Path cell, String prog, Path tmp) throws IOException, InterruptedException {
    List<String> cmd = new ArrayList<>();
    cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
    cmd.addAll(childJvmOptions(ManagementFactory.getRuntimeMXBean().getInputArguments(),
        System.getenv("ROBOTRUN_BENCH_JAVA_OPTS")));
    cmd.addAll(List.of("-cp", System.getProperty("java.class.path"), Main.class.getName(), "gui",
        "--scenario", cell.toString(), "--width", String.valueOf(width), "--height", String.valueOf(height),
        "--bench-seconds", String.valueOf(seconds), "--bench-program", prog));
    ProcessBuilder pb = new ProcessBuilder(cmd).redirectError(ProcessBuilder.Redirect.INHERIT);
    // the workspace copy, its settings and the "last workspace" stay in the temporary folder
    pb.environment().put("ROBOTRUN_DATA_DIR", tmp.resolve("data").toString());
    pb.environment().put("ROBOTRUN_CONFIG_DIR", tmp.resolve("config").toString());
    pb.environment().put("ROBOTRUN_LABS_HOME", tmp.resolve("labs").toString());
    pb.environment().remove("ROBOTRUN_PRINT_LCD_ON_EXIT");
    PrintWriter out = spec.commandLine().getOut();
    Process p = pb.start();
    long closeRequestedUs = -1;
    int phases = 0;
    try (BufferedReader r = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
      for (String line; (line = r.readLine()) != null; ) {
        if (line.startsWith("phase=")) {
          out.println(line);
          out.flush();
          phases++;
        } else if (line.startsWith("close_requested_epoch_us=")) {
          closeRequestedUs = Long.parseLong(line.substring(line.indexOf('=') + 1).trim());
        } else {
          System.err.println(TerminalText.safe(line));
        }
      }
    }
    double limit = 2 + 3 * (seconds + 1) + 120;
    if (!p.waitFor((long) limit, TimeUnit.SECONDS)) {
      p.destroyForcibly();
      throw new UserError("bench window: the window did not close within " + (long) limit + " s", Main.EXIT_FAILED);
    }
    long endUs = WindowBench.epochMicros(Instant.now());
    if (p.exitValue() != 0) {
      throw new UserError("bench window: the window ended with exit code " + p.exitValue()
          + " (its message is above)", Main.EXIT_FAILED);
    }
    if (phases != 3 || closeRequestedUs < 0) {
      throw new UserError("bench window: the window ended before the phases were done", Main.EXIT_FAILED);
    }
    out.printf(Locale.ROOT, "close_ms=%d%n", Math.round((endUs - closeRequestedUs) / 1000.0));
    out.flush();
    return Main.EXIT_OK;
  }

  /**
   * The JVM options of this process for the window's, less those that must not be shared (the
   * class-data archive both would write, a flight recording to the same file, a debugger's port),
   * plus {@code extra} (split at spaces).
   */
  static List<String> childJvmOptions(List<String> mine, String extra) {
    List<String> out = new ArrayList<>();
    for (String a : mine) {
      if (a.startsWith("-XX:SharedArchiveFile") || a.equals("-XX:+AutoCreateSharedArchive") || a.startsWith("-Xlog:cds")
          || a.startsWith("-Xlog:aot") || a.startsWith("-XX:StartFlightRecording") || a.startsWith("-agentlib:jdwp")) {
        continue;
      }
      out.add(a);
    }
    if (extra != null && !extra.isBlank()) {
      out.addAll(List.of(extra.trim().split("\\s+")));
    }
    return out;
  }

  private static Path shippedScenario() {
    for (Path p : GuiCommand.shipped("scenarios/pick-and-place.json")) {
      if (Files.isRegularFile(p)) {
        return p;
      }
    }
    throw new UserError("--scenario: the shipped scenarios/pick-and-place.json is not beside the application or in "
        + "the current folder; give a scenario");
  }

  /** The programs of the scenario's first robot, the cell-wide list first. */
  private static List<String> programNames(Path cell) {
    Scenario sc = ScenarioFiles.load(cell);
    List<Path> files = new ArrayList<>(sc.programs());
    if (!sc.robots().isEmpty()) {
      files.addAll(sc.robots().get(0).programs());
    }
    try {
      return RunCommand.loadPrograms(files).stream().map(Program::name).toList();
    } catch (IOException e) {
      throw new UserError("--scenario: " + cell + ": cannot read a program (" + e.getMessage() + ")");
    }
  }

  private static void deleteTree(Path dir) {
    try (var walk = Files.walk(dir)) {
      for (Path p : walk.sorted(java.util.Comparator.reverseOrder()).toList()) {
        Files.deleteIfExists(p);
      }
    } catch (IOException e) {
      System.err.println("robotrun: could not remove the temporary folder " + dir + " (" + e.getMessage() + ")");
    }
  }
}
