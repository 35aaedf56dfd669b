package org.robotrun.app;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.robotrun.io.AtomicFiles;
import org.robotrun.io.BoundedFiles;
import org.robotrun.io.Diagnostic;
import org.robotrun.io.LsReadResult;
import org.robotrun.io.LsReader;
import org.robotrun.io.ScenarioReader;
import org.robotrun.io.Workspace;
import org.robotrun.io.WorkspaceException;
import org.robotrun.program.Program;
import org.robotrun.world.Scenario;

/** Whole-workspace file operations of the File menu and the command line. */
final class WorkspaceFiles {
  private WorkspaceFiles() {}

  /**
   * Makes a new workspace in {@code dir} copied from a scenario: its cell, and its programs
   * byte for byte. The scenario and its files are only read.
   *
   * @return the new workspace folder
   * @throws UserError when the scenario cannot be read or the folder is not new or empty
   */
  static Path createFromScenario(Path scenarioFile, Path dir) {
    Scenario sc = ScenarioFiles.load(scenarioFile);
    try {
      RunCommand.loadPrograms(sc.programs());  // every program must read cleanly before anything is made
      for (var r : sc.robots()) {
        RunCommand.loadPrograms(r.programs());
      }
    } catch (IOException e) {
      throw new UserError(scenarioFile + ": cannot read a program (" + e.getMessage() + ")");
    }
    if (Files.exists(dir) && !isEmptyFolder(dir)) {
      throw new UserError(dir + ": not an empty folder; a new workspace needs a new or empty folder");
    }
    try {
      Files.createDirectories(dir.resolve(Workspace.PROGRAMS));
      List<Path> firstRobots = new ArrayList<>(sc.programs());
      firstRobots.addAll(sc.robots().get(0).programs());
      for (Path from : firstRobots) {
        String name = LsReader.read(from).program().name();
        AtomicFiles.write(dir.resolve(Workspace.PROGRAMS).resolve(name + ".LS"),
            BoundedFiles.read(from, LsReader.MAX_FILE_BYTES, ".LS programs"));
      }
      // Every other robot's programs in its own folder (Workspace.robotFolder).
      for (int i = 1; i < sc.robots().size(); i++) {
        Path folder = dir.resolve(Workspace.PROGRAMS).resolve(Workspace.robotFolder(sc.robots().get(i).name()));
        Files.createDirectories(folder);
        for (Path from : sc.robots().get(i).programs()) {
          String name = LsReader.read(from).program().name();
          AtomicFiles.write(folder.resolve(name + ".LS"), BoundedFiles.read(from, LsReader.MAX_FILE_BYTES, ".LS programs"));
        }
      }
    } catch (IOException e) {
      throw new UserError(dir + ": cannot create the workspace (" + Workspace.describe(e) + ")", Main.EXIT_FAILED);
    }
    // In a workspace the programs are its files: the robots keep their main programs, not the paths.
    List<org.robotrun.world.RobotSetup> robots = sc.robots().stream().map(r -> r.withPrograms(List.of(), r.mainProgram()))
        .toList();
    Scenario cell = sc.withRobots(robots).withPrograms(List.of(), sc.mainProgram());
    try (Workspace ws = Workspace.open(dir, cell)) {
      return ws.folder();
    } catch (WorkspaceException e) {
      throw new UserError(e.getMessage());
    }
  }

  static boolean isEmptyFolder(Path dir) {
    if (!Files.isDirectory(dir)) {
      return false;
    }
    try (Stream<Path> s = Files.list(dir)) {
      return s.findAny().isEmpty();
    } catch (IOException e) {
      return false;
    }
  }

  /** Copies the workspace's files (as saved) into a new or empty folder; "" or the problem. */
  static String saveCopy(Path from, Path to) {
    if (Files.exists(to) && !isEmptyFolder(to)) {
      return to + ": not an empty folder; a copy needs a new or empty folder";
    }
    try {
      Files.createDirectories(to.resolve(Workspace.PROGRAMS));
      AtomicFiles.write(to.resolve(Workspace.CELL),
          BoundedFiles.read(from.resolve(Workspace.CELL), ScenarioReader.MAX_FILE_BYTES, "cell files"));
      try (Stream<Path> s = Files.list(from.resolve(Workspace.PROGRAMS))) {
        for (Path f : s.sorted().toList()) {
          if (Files.isRegularFile(f)) {
            AtomicFiles.write(to.resolve(Workspace.PROGRAMS).resolve(f.getFileName().toString()),
                BoundedFiles.read(f, LsReader.MAX_FILE_BYTES, ".LS programs"));
          } else if (Files.isDirectory(f)) {
            // another robot's programs (programs/ROBOT/)
            Path sub = Files.createDirectories(to.resolve(Workspace.PROGRAMS).resolve(f.getFileName().toString()));
            try (Stream<Path> inner = Files.list(f)) {
              for (Path g : inner.filter(Files::isRegularFile).sorted().toList()) {
                AtomicFiles.write(sub.resolve(g.getFileName().toString()),
                    BoundedFiles.read(g, LsReader.MAX_FILE_BYTES, ".LS programs"));
              }
            }
          }
        }
      }
      return "";
    } catch (IOException e) {
      return "cannot copy the workspace to " + to + ": " + Workspace.describe(e);
    }
  }

  /** Reads .LS files; the programs that read cleanly, and one message per file that did not. */
  static List<Program> readPrograms(List<Path> files, List<String> problems) {
    List<Program> out = new ArrayList<>();
    for (Path f : files) {
      try {
        LsReadResult r = LsReader.readCheckingFileName(f);
        List<Diagnostic> errors = r.diagnostics().stream().filter(Diagnostic::isError).toList();
        if (errors.isEmpty() && r.program() != null) {
          out.add(r.program());
        } else {
          problems.add(String.join("\n", errors.stream().limit(5).map(Diagnostic::toString).toList()));
        }
      } catch (IOException e) {
        problems.add(f + ": cannot read (" + Workspace.describe(e) + ")");
      }
    }
    return out;
  }

  /** Writes {@code p} as a .LS file; "" or the problem. */
  static String export(Program p, Path file) {
    try {
      AtomicFiles.write(file, org.robotrun.io.LsWriter.write(p).getBytes(StandardCharsets.UTF_8));
      return "";
    } catch (IOException e) {
      return "cannot write " + file + ": " + Workspace.describe(e);
    }
  }
}
