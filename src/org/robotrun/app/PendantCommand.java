package org.robotrun.app;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import org.robotrun.io.Diagnostic;
import org.robotrun.io.FileFormatException;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;
import org.robotrun.io.LsWriter;
import org.robotrun.io.TerminalText;
import org.robotrun.io.RobotDefinitions;
import org.robotrun.pendant.KeyScript;
import org.robotrun.pendant.Pendant;
import org.robotrun.pendant.RobotControl;
import org.robotrun.pendant.StandInRobotControl;
import org.robotrun.program.Program;
import org.robotrun.world.Scenario;
import org.robotrun.sim.DefaultCell;
import org.robotrun.sim.ScenarioCell;
import org.robotrun.sim.Simulation;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code robotrun pendant}: drives the teach pendant from a .keys script and prints its LCD. */
@Command(
    name = "pendant",
    mixinStandardHelpOptions = true,
    description = {
      "Run a .keys script on the teach pendant and print the LCD as text at every SHOW.",
      "Script lines: a key (ENTER, F1, SHIFT+FWD, +X/J1, DOWN *3), TYPE text, HOLD key, RELEASE key, WAIT seconds (simulated), SHOW, and # comments. See docs/pendant.md.",
      "By default the pendant drives the simulation's controller: the scenario's first robot, or without --scenario the default cell (default robot at HOME, UTOOL 1 a 100 mm pointer, UFRAME 1 = WORLD).",
      "--controller stand-in uses the stand-in controller instead: the same program interpreter on a toy gantry arm, no robot kinematics, no scenario.",
      "With --workspace DIR the workspace is opened (or created) first and everything the script changes is saved back to it when the script ends (and at each SHOW); a second RobotRun on the same workspace opens it read-only.",
      "Exit codes: 0 script ran (pendant errors show on its prompt line), 1 --save or the workspace could not be written, 2 bad option, unreadable program or malformed script (file:line)."
    })
public final class PendantCommand implements Callable<Integer> {
  @Option(names = "--keys", required = true, paramLabel = "FILE.keys", description = "The key script to run.")
  Path keys;

  @Option(names = "--program", paramLabel = "FILE.LS",
      description = "A TP program (.LS) to load before the script runs; repeat for more. A file with errors is exit 2.")
  List<Path> programs = new java.util.ArrayList<>();

  @Option(names = "--controller", paramLabel = "sim|stand-in", defaultValue = "sim",
      description = "Which controller the pendant drives: sim (default) or stand-in.")
  String controller;

  @Option(names = "--save", paramLabel = "DIR",
      description = "After the script, write every program to DIR/NAME.LS (the directory must exist).")
  Path saveDir;

  @Option(names = "--scenario", paramLabel = "FILE",
      description = "Scenario JSON to load first (its cell, frames, registers and programs; docs/scenario-format.md); "
          + "the pendant drives its first robot. Default: the default cell.")
  Path scenario;

  @Option(names = "--workspace", paramLabel = "DIR",
      description = "A workspace folder to open (or create) first: its cell, saved state and programs; "
          + "what the script changes is saved back to it as the window saves it (docs/workspace.md).")
  Path workspace;

  @Option(names = "--max-wall-seconds", paramLabel = "N", defaultValue = "3600",
      description = "Stop with exit code 1 when the script has run this long in real (wall-clock) time, 1.."
          + "86400 (default: ${DEFAULT-VALUE}). A safety net for graders; results are otherwise deterministic.")
  double maxWallSeconds;

  @Spec
  CommandSpec spec;

  @Override
  public Integer call() {
    if (saveDir != null && !Files.isDirectory(saveDir)) {
      throw new UserError("--save: the directory " + saveDir + " does not exist");
    }
    WallClock.checkOption(maxWallSeconds);
    List<String> lines = InputFiles.lines("--keys", keys, KeyScript.MAX_FILE_BYTES, "key scripts");
    KeyScript script = switch (KeyScript.parse(keys.toString(), lines)) {
      case KeyScript.Parsed.Ok ok -> ok.script();
      case KeyScript.Parsed.Bad bad -> throw new UserError(bad.error().display());
    };
    List<Path> programFiles = new java.util.ArrayList<>();
    WorkspaceSession session = null;
    if (workspace != null && (scenario != null || !controller.equals("sim"))) {
      throw new UserError("--workspace: give it alone (a workspace has its own cell; it needs --controller sim)");
    }
    RobotControl control = switch (controller) {
      case "sim" -> {
        Simulation sim;
        if (workspace != null) {
          session = WorkspaceSession.open(workspace, false, java.util.Optional::empty,
              m -> System.err.println("robotrun: " + m));
          if (!session.problems().isEmpty()) {
            System.err.println("robotrun: " + session.problems());
          }
          sim = session.sim;
        } else if (scenario != null) {
          Scenario sc = ScenarioFiles.load(scenario);
          try {
            sim = ScenarioCell.build(sc, RobotDefinitions::load, Simulation.DEFAULT_TICK_SEC);
          } catch (FileFormatException | IllegalArgumentException e) {
            throw new UserError(scenario + ": " + e.getMessage());
          }
          programFiles.addAll(sc.programs());
        } else {
          sim = DefaultCell.simulation(RobotDefinitions.defaultRobot());
        }
        // the pendant drives the scenario's first robot
        yield new SimRobotControl(sim, sim.controllers().get(0));
      }
      case "stand-in" -> {
        if (scenario != null) {
          throw new UserError("--scenario needs the simulation controller (--controller sim)");
        }
        yield new StandInRobotControl(new RobotFrameTeacher());
      }
      default -> throw new UserError("--controller: expected sim or stand-in, got '" + controller + "'");
    };
    programFiles.addAll(programs);
    for (Path file : programFiles) {
      control.saveProgram(readProgram(file));
    }
    PrintWriter out = spec.commandLine().getOut();
    WallClock clock = WallClock.start(maxWallSeconds);
    WorkspaceSession ws = session;
    int stoppedAt = script.run(new Pendant(control, new LsLineParser()), text -> {
      out.print(TerminalText.safe(text));
      if (ws != null) {
        ws.autosave.poll(System.nanoTime());
      }
    }, clock::expired);
    out.flush();
    if (session != null) {
      String problem = session.autosave.saveNow(10_000);
      session.close();
      if (!problem.isEmpty() && !session.workspace.readOnly()) {
        throw new UserError("--workspace: " + problem, Main.EXIT_FAILED);
      }
    }
    if (stoppedAt > 0) {
      throw new UserError(keys + ":" + stoppedAt + ": stopped: the script ran longer than --max-wall-seconds "
          + WallClock.format(maxWallSeconds) + " s of real time", Main.EXIT_FAILED);
    }
    if (saveDir != null) {
      for (String name : control.programNames()) {
        Path file = saveDir.resolve(name + ".LS");
        try {
          LsWriter.write(control.program(name).orElseThrow(), file);
        } catch (IOException e) {
          throw new UserError("--save: cannot write " + file + " (" + e.getMessage() + ")", Main.EXIT_FAILED);
        }
      }
    }
    return Main.EXIT_OK;
  }

  private static Program readProgram(Path file) {
    LsReadResult r;
    try {
      r = LsReader.read(file);
    } catch (java.nio.file.NoSuchFileException e) {
      throw new UserError("--program: no such file " + file);
    } catch (IOException e) {
      throw new UserError("--program: cannot read " + file + " (" + e.getMessage() + ")");
    }
    if (r.hasErrors() || r.program() == null) {
      String first = r.diagnostics().stream().filter(Diagnostic::blocksLoading).findFirst().map(Diagnostic::toString)
          .orElse(file + ": not a program");
      throw new UserError("--program: " + first);
    }
    return r.program();
  }
}
