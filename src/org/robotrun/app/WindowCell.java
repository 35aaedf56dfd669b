package org.robotrun.app;

import imgui.ImGui;
import org.robotrun.io.TerminalText;
import org.robotrun.ui.Txt;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.function.Supplier;
import org.robotrun.io.UserDirs;
import org.robotrun.io.Workspace;
import org.robotrun.program.Program;
import org.robotrun.sim.Controller;
import org.robotrun.ui.FileMenu;
import org.robotrun.world.CameraView;

/** The window's side of one open workspace: its session, save state in the menu bar, outside edits. Window thread only. */
final class WindowCell {
  final WorkspaceSession session;
  /** Autosave reports arrive on the writer thread; the window shows them. */
  private final Queue<String> reports;

  private final String name;
  private java.util.function.Consumer<String> tell = m -> {};
  private Runnable reopen = () -> {};

  private WindowCell(WorkspaceSession session, Queue<String> reports, String name) {
    this.session = session;
    this.name = name;
    this.reports = reports;
  }

  /**
   * Opens the workspace in {@code dir} (UserError when it cannot be opened at all) and remembers
   * it as the last one; problems at open go to {@code tell} (the File menu, once it exists).
   */
  static WindowCell open(Path dir, UserDirs dirs, java.util.function.Consumer<String> tell,
      Supplier<Optional<CameraView>> camera) {
    Queue<String> reports = new ConcurrentLinkedQueue<>();
    WorkspaceSession s = WorkspaceSession.open(dir, false, camera, m -> {
      System.err.println("robotrun: " + TerminalText.safe(m));
      reports.add(m);
    });
    String problems = s.problems();
    if (!problems.isEmpty()) {
      System.err.println("robotrun: " + TerminalText.safe(problems));
      tell.accept(problems);
    }
    boolean handIn = dir.getFileName() != null && dir.getFileName().toString().toLowerCase(java.util.Locale.ROOT).endsWith(".zip");
    try {
      if (!handIn) {  // a hand-in opens from a temporary copy, which is not worth remembering
        dirs.remember(s.workspace.folder());
      }
    } catch (IOException e) {
      System.err.println(TerminalText.safe("robotrun: cannot remember the last workspace in " + dirs.configDir() + " (" + e.getMessage() + ")"));
    }
    return new WindowCell(s, reports, handIn ? dir.getFileName().toString() : s.workspace.name());
  }

  String title() {
    return "RobotRun — " + name + (session.workspace.readOnly() ? " (read-only)" : "");
  }

  /** In the menu bar: the workspace and whether its last save worked. Shows autosave reports. */
  void drawSaveState(FileMenu menu) {
    for (String r; (r = reports.poll()) != null; ) {
      if (!r.startsWith("saved again")) {
        menu.tell(r);
      }
    }
    ImGui.separator();
    Txt.disabled(session.workspace.folder().toString());
    if (session.workspace.readOnly()) {
      Txt.colored(0.95f, 0.7f, 0.2f, 1f, "read-only");
    } else if (!session.autosave.problem().isEmpty()) {
      Txt.colored(0.95f, 0.3f, 0.3f, 1f, "NOT SAVED");
      if (ImGui.isItemHovered()) {
        Txt.tooltip(session.autosave.problem());
      }
    } else if (!session.autosave.status().isEmpty()) {
      Txt.disabled(session.autosave.status());
    }
  }

  /**
   * The window got the focus back: programs changed on disk meanwhile are reloaded when they
   * were not edited here; an edited one makes the menu ask which version to keep.
   */
  void checkExternalEdits(FileMenu menu) {
    Workspace ws = session.workspace;
    if (ws.readOnly()) {
      return;
    }
    List<String> problems = new ArrayList<>();
    for (Workspace.ExternalChange ch : ws.externalChanges()) {
      if (ch.deleted()) {
        menu.tell(ch.file() + " was deleted outside RobotRun; program " + ch.programName()
            + " is still open here and is saved again.");
        continue;
      }
      // A later robot's file is known as "ROBOT/NAME" (programs/ROBOT/NAME.LS).
      Controller c = controllerOf(ch.file());
      String name = ch.programName().contains("/") ? ch.programName().substring(ch.programName().indexOf('/') + 1)
          : ch.programName();
      Optional<Program> mine = name.isEmpty() ? Optional.empty() : c.program(name);
      if (mine.isPresent() && !ws.isSaved(ch.programName(), mine.get())) {
        menu.askConflict(ch.file());
        continue;
      }
      takeFile(ch.file(), problems);
    }
    problems.forEach(menu::tell);
  }

  /** Loads the program in {@code file} into the controller (a message in {@code problems} when it cannot be read). */
  void takeFile(Path file, List<String> problems) {
    session.workspace.reread(file, problems).ifPresent(p -> controllerOf(file).saveProgram(p));
  }

  /** The controller whose program folder holds {@code file}: the first robot's for programs/, else the robot's own. */
  private Controller controllerOf(Path file) {
    Optional<String> folder = session.workspace.robotFolderOf(file);
    for (Controller c : session.sim.controllers().subList(1, session.sim.controllers().size())) {
      if (folder.isPresent() && Workspace.robotFolder(c.name()).equals(folder.get())) {
        return c;
      }
    }
    return session.sim.controllers().get(0);
  }

  /** Where a refused scenario switch is told, and how the workspace is opened again after one. */
  void onSwitch(java.util.function.Consumer<String> tell, Runnable reopen) {
    this.tell = tell;
    this.reopen = reopen;
  }

  /**
   * The cell editor made another scenario active: pin the workspace's content after the switch
   * and open the workspace again; when the chosen scenario cannot run, undo the choice and say why.
   */
  void switchScenario(org.robotrun.world.CellEditor editor, Optional<CameraView> camera) {
    if (session.workspace.readOnly()) {
      editor.undo();
      tell.accept("This workspace is read-only (" + session.workspace.readOnlyReason()
          + "): its scenarios can be looked at in the list but not switched.");
      return;
    }
    String why = ScenarioSwitch.prepare(session, editor, camera);
    if (!why.isEmpty()) {
      editor.undo();
      tell.accept(why);
      return;
    }
    reopen.run();
  }

  void close() {
    session.close();
  }

  /** Closes (final save) and returns the save problem left, "" when everything is on disk. */
  String closeAndReport() {
    String problem = session.workspace.readOnly() ? "" : session.autosave.saveNow(10_000);
    session.close();
    return problem.isEmpty() ? "" : "your last changes could not be saved: " + problem;
  }
}
