package org.robotrun.app;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.robotrun.io.HandIn;
import org.robotrun.io.HandInException;
import org.robotrun.io.TerminalText;
import org.robotrun.io.UserDirs;
import org.robotrun.program.Program;
import org.robotrun.sim.Controller;
import org.robotrun.ui.FileMenu;

/** What the window's File menu does, on the current {@link WindowCell}. Window thread only. */
final class GuiFileActions implements FileMenu.Actions {
  private final UserDirs dirs;
  private final Supplier<WindowCell> current;
  private final Consumer<Path> switchTo;
  private final Runnable quit;
  private FileMenu menu;

  /** @param switchTo closes this window and opens one on the given workspace folder */
  GuiFileActions(UserDirs dirs, Supplier<WindowCell> current, Consumer<Path> switchTo, Runnable quit) {
    this.dirs = dirs;
    this.current = current;
    this.switchTo = switchTo;
    this.quit = quit;
  }

  void setMenu(FileMenu menu) {
    this.menu = menu;
  }

  private Controller controller() {
    return current.get().session.sim.controllers().get(0);
  }

  @Override
  public Path workspaceFolder() {
    return current.get().session.workspace.folder();
  }

  @Override
  public List<Path> recentWorkspaces() {
    return dirs.recentWorkspaces();
  }

  @Override
  public List<String> programNames() {
    return controller().programNames().stream().sorted().toList();
  }

  @Override
  public String openWorkspace(Path folder, boolean mustBeNew) {
    Path abs = folder.toAbsolutePath().normalize();
    if (abs.equals(workspaceFolder())) {
      return "this workspace is already open";
    }
    if (mustBeNew && Files.exists(abs) && !WorkspaceFiles.isEmptyFolder(abs)) {
      return abs + ": not an empty folder; a new workspace needs a new or empty folder";
    }
    // Everything is on disk before the window lets go of this workspace.
    String saved = current.get().session.autosave.saveNow(10_000);
    if (!saved.isEmpty() && !current.get().session.workspace.readOnly()) {
      return "this workspace could not be saved, so it stays open: " + saved;
    }
    if (!mustBeNew && Files.exists(abs) && !Files.exists(abs.resolve(org.robotrun.io.Workspace.CELL))
        && !WorkspaceFiles.isEmptyFolder(abs)) {
      return abs + ": not a workspace (no cell.json); open a workspace folder, or pick a new or empty folder with New workspace";
    }
    switchTo.accept(abs);
    return "";
  }

  @Override
  public String openScenario(Path file) {
    try {
      Path dir = WorkspaceFiles.createFromScenario(file, dirs.newWorkspaceFor(GuiCommand.stem(file)));
      String m = openWorkspace(dir, false);
      if (m.isEmpty()) {
        System.err.println(TerminalText.safe("robotrun: a new workspace was made from " + file + " in " + dir + " (the scenario is not changed)"));
      }
      return m;
    } catch (UserError e) {
      return e.getMessage();
    }
  }

  @Override
  public String saveCopy(Path folder) {
    boolean readOnly = current.get().session.workspace.readOnly();
    // A read-only workspace (a hand-in) refuses edits, so what is on disk is all there is to copy.
    String saved = readOnly ? "" : saveNow();
    if (!saved.isEmpty()) {
      return saved;
    }
    Path to = folder.toAbsolutePath().normalize();
    String m = WorkspaceFiles.saveCopy(workspaceFolder(), to);
    if (!m.isEmpty()) {
      return m;
    }
    if (readOnly) {
      // "save as a new workspace": the copy is the student's to edit, so the window opens it
      String opened = openWorkspace(to, false);
      return opened.isEmpty() ? "" : "A copy was saved in " + to + ", but it could not be opened: " + opened;
    }
    return "A copy was saved in " + folder + " (you keep working in " + workspaceFolder() + ").";
  }

  @Override
  public String importPrograms(List<Path> files) {
    if (current.get().session.workspace.readOnly()) {
      return "this workspace is read-only: " + current.get().session.workspace.readOnlyReason();
    }
    List<String> problems = new ArrayList<>();
    List<Program> programs = WorkspaceFiles.readPrograms(files, problems);
    List<String> done = new ArrayList<>();
    for (Program p : programs) {
      boolean replaced = controller().program(p.name()).isPresent();
      controller().saveProgram(p);
      done.add(p.name() + (replaced ? " (replaced the one here)" : ""));
    }
    String m = done.isEmpty() ? "" : "Imported " + String.join(", ", done) + ".";
    if (!problems.isEmpty()) {
      m += (m.isEmpty() ? "" : "\n\n") + "Not imported:\n" + String.join("\n", problems);
    }
    return m;
  }

  @Override
  public String exportProgram(String name, Path file) {
    return controller().program(name).map(p -> WorkspaceFiles.export(p, file)).orElse("no program " + name);
  }

  @Override
  public String handIn(String student, Path zip, boolean replace) {
    // A read-only workspace hands in what is on disk.
    String saved = current.get().session.workspace.readOnly() ? "" : saveNow();
    if (!saved.isEmpty()) {
      return "cannot hand in: " + saved;
    }
    try {
      HandIn.Manifest m = HandIn.write(workspaceFolder(), zip, student, new Main.Version().getVersion()[0]
          .replace("robotrun ", ""), replace);
      return "handed in: " + zip + " (" + m.files().size() + " files, SHA-256 in manifest.json)";
    } catch (HandInException e) {
      return e.getMessage();
    }
  }

  @Override
  public String saveNow() {
    WindowCell c = current.get();
    if (c.session.workspace.readOnly()) {
      return "nothing is saved: " + c.session.workspace.readOnlyReason();
    }
    return c.session.autosave.saveNow(10_000);
  }

  @Override
  public void quit() {
    quit.run();
  }

  @Override
  public void resolveConflict(Path file, boolean takeFile) {
    WindowCell c = current.get();
    if (takeFile) {
      List<String> problems = new ArrayList<>();
      c.takeFile(file, problems);
      problems.forEach(menu::tell);
    } else {
      c.session.workspace.keepOurs(file);
    }
  }
}
