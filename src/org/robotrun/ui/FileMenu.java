package org.robotrun.ui;

import static org.lwjgl.glfw.GLFW.*;

import imgui.ImGui;
import imgui.flag.ImGuiWindowFlags;
import imgui.type.ImString;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import java.util.function.Consumer;

/**
 * The window's File menu (drawn inside the main menu bar, which the window owns) with its
 * shortcuts Ctrl+O, Ctrl+S, Ctrl+Q, and the small dialogs it needs: the hand-in form, a typed
 * path where no system file dialog is available, messages, and the question asked when a
 * program edited in the window was also changed on disk.
 */
public final class FileMenu implements Workbench.MenuContributor {
  /** What the menu asks the application to do; each returns a message for the user, "" when all went well. */
  public interface Actions {
    Path workspaceFolder();

    List<Path> recentWorkspaces();

    List<String> programNames();

    String openWorkspace(Path folder, boolean mustBeNew);

    String openScenario(Path file);

    String saveCopy(Path folder);

    String importPrograms(List<Path> files);

    String exportProgram(String name, Path file);

    /** Writes the hand-in; {@code replace} once the user agreed to replace an existing file. */
    String handIn(String student, Path zip, boolean replace);

    String saveNow();

    void quit();

    /** A conflict the user settled: keep the window's program, or load the file's. */
    void resolveConflict(Path file, boolean takeFile);
  }

  private final Actions actions;
  private final FileDialogs dialogs;
  private final Deque<String> messages = new ArrayDeque<>();
  private final Deque<Path> conflicts = new ArrayDeque<>();
  private String status = "";
  private double statusUntil;
  private Runnable statusLine = () -> {};
  // typed-path fallback
  private String pathPrompt = "";
  private final ImString typedPath = new ImString(1024);
  private Consumer<Path> pathUse;
  private boolean openPathPopup;
  // hand-in form
  private boolean openHandIn;
  private final ImString student = new ImString(200);
  private final ImString handInPath = new ImString(1024);
  private boolean askReplace;
  private String handInError = "";

  public FileMenu(Actions actions, FileDialogs dialogs) {
    this.actions = actions;
    this.dialogs = dialogs;
  }

  /** Shows a message in a small window (problems at open, save failures). */
  public void tell(String message) {
    if (!message.isBlank()) {
      messages.add(message);
    }
  }

  /** Asks which version of the program in {@code file} to keep (it was edited here and changed on disk). */
  public void askConflict(Path file) {
    if (!conflicts.contains(file)) {
      conflicts.add(file);
    }
  }

  /** Draws more in the menu bar after the File menu (the workspace and its save state). */
  public void setStatusLine(Runnable line) {
    statusLine = line;
  }

  /** A short note in the menu bar ("Saved", "saved 10:02:03"). */
  public void setStatus(String text, double untilSec) {
    status = text;
    statusUntil = untilSec;
  }

  /**
   * Handles Ctrl+O, Ctrl+S and Ctrl+Q (Cmd on macOS) when a key is pressed; returns whether the
   * key was one of them (then it must not reach the pendant).
   */
  public boolean onShortcut(int glfwKey, int mods) {
    if ((mods & (GLFW_MOD_CONTROL | GLFW_MOD_SUPER)) == 0) {
      return false;
    }
    switch (glfwKey) {
      case GLFW_KEY_O -> openWorkspace(false);
      case GLFW_KEY_S -> saveNow();
      case GLFW_KEY_Q -> actions.quit();
      default -> {
        return false;
      }
    }
    return true;
  }

  private void saveNow() {
    String m = actions.saveNow();
    if (m.isEmpty()) {
      status = "Saved";
      statusUntil = ImGui.getTime() + 2;
    } else {
      tell(m);
    }
  }

  /**
   * Draws the File menu and the workspace's status; call between {@code beginMainMenuBar} and
   * {@code endMainMenuBar}. Its dialogs are drawn by {@link #drawPopups()}, after the other windows.
   */
  @Override
  public void drawMenus() {
    drawMenu();
    statusLine.run();
  }

  /** Draws the File menu; call between {@code beginMainMenuBar} and {@code endMainMenuBar}. */
  public void drawMenu() {
    if (ImGui.beginMenu("File")) {
      if (ImGui.menuItem("New workspace...")) {
        openWorkspace(true);
      }
      if (ImGui.menuItem("Open workspace...", "Ctrl+O")) {
        openWorkspace(false);
      }
      if (ImGui.menuItem("Open scenario...")) {
        choose("Open scenario: the scenario file (.rrcell or .json); it is copied into a new workspace",
            () -> dialogs.open("Scenario", "rrcell,json", false, null), p -> tell(actions.openScenario(p)));
      }
      if (ImGui.beginMenu("Recent workspaces")) {
        List<Path> recent = actions.recentWorkspaces();
        if (recent.isEmpty()) {
          ImGui.menuItem("(none)", "", false, false);
        }
        for (Path p : recent) {
          if (ImGui.menuItem(p.toString())) {
            tell(actions.openWorkspace(p, false));
          }
        }
        ImGui.endMenu();
      }
      ImGui.separator();
      if (ImGui.menuItem("Save now", "Ctrl+S")) {
        saveNow();
      }
      if (ImGui.menuItem("Save a copy as...")) {
        choose("Save a copy: a new or empty folder for the copy",
            () -> dialogs.pickFolder(actions.workspaceFolder().getParent()), p -> tell(actions.saveCopy(p)));
      }
      ImGui.separator();
      if (ImGui.menuItem("Import programs (.LS)...")) {
        pending("Import programs: a .LS file", dialogs.open("TP program", "LS,ls", true, null),
            p -> tell(actions.importPrograms(List.of(p))), paths -> tell(actions.importPrograms(paths)));
      }
      if (ImGui.beginMenu("Export program (.LS)")) {
        List<String> names = actions.programNames();
        if (names.isEmpty()) {
          ImGui.menuItem("(no programs)", "", false, false);
        }
        for (String name : names) {
          if (ImGui.menuItem(name)) {
            choose("Export " + name + ": the .LS file to write",
                () -> dialogs.save("TP program", "LS", null, name + ".LS"), p -> tell(actions.exportProgram(name, p)));
          }
        }
        ImGui.endMenu();
      }
      ImGui.separator();
      if (ImGui.menuItem("Hand in...")) {
        openHandIn = true;
        Path ws = actions.workspaceFolder();
        if (handInPath.get().isEmpty()) {
          handInPath.set(ws.resolveSibling(ws.getFileName() + "-handin.zip").toString());
        }
      }
      ImGui.separator();
      if (ImGui.menuItem("Quit", "Ctrl+Q")) {
        actions.quit();
      }
      ImGui.endMenu();
    }
    if (!status.isEmpty() && ImGui.getTime() < statusUntil) {
      Txt.disabled(status);
    }
  }

  @Override
  public long nextRedrawNanos() {
    if (status.isEmpty()) {
      return Long.MAX_VALUE;
    }
    double left = statusUntil - ImGui.getTime();
    return left <= 0 ? Long.MAX_VALUE : System.nanoTime() + (long) (left * 1e9) + 1_000_000L;
  }

  private void openWorkspace(boolean mustBeNew) {
    choose(mustBeNew ? "New workspace: a new or empty folder" : "Open workspace: the workspace folder (it holds cell.json)",
        () -> dialogs.pickFolder(actions.workspaceFolder().getParent()), p -> tell(actions.openWorkspace(p, mustBeNew)));
  }

  private void choose(String prompt, java.util.function.Supplier<FileDialogs.Answer> dialog, Consumer<Path> use) {
    pending(prompt, dialog.get(), use, paths -> use.accept(paths.get(0)));
  }

  private void pending(String prompt, FileDialogs.Answer answer, Consumer<Path> useOne, Consumer<List<Path>> useMany) {
    switch (answer) {
      case FileDialogs.Answer.Chosen c -> {
        if (!c.paths().isEmpty()) {
          useMany.accept(c.paths());
        }
      }
      case FileDialogs.Answer.Cancelled c -> { }
      case FileDialogs.Answer.Unavailable u -> {
        pathPrompt = prompt + "\n\n(" + u.reason() + ". Type the path instead; from a terminal, "
            + "'robotrun --workspace DIR' opens a workspace and 'robotrun run --workspace DIR|FILE.zip' runs one.)";
        pathUse = useOne;
        typedPath.set("");
        openPathPopup = true;
      }
    }
  }

  /** Draws the menu's dialogs; call once per frame, after the other windows and outside the menu bar. */
  @Override
  public void drawPopups() {
    if (openPathPopup) {
      ImGui.openPopup("Path##file");
      openPathPopup = false;
    }
    if (ImGui.beginPopupModal("Path##file", ImGuiWindowFlags.AlwaysAutoResize)) {
      Txt.wrapped(pathPrompt);
      ImGui.setNextItemWidth(ImGui.getFontSize() * 40);
      if (ImGui.isWindowAppearing()) {
        ImGui.setKeyboardFocusHere();
      }
      boolean enter = ImGui.inputText("##path", typedPath, imgui.flag.ImGuiInputTextFlags.EnterReturnsTrue);
      if ((ImGui.button("OK") || enter) && !typedPath.get().isBlank()) {
        ImGui.closeCurrentPopup();
        Consumer<Path> use = pathUse;
        pathUse = null;
        try {
          use.accept(Path.of(expandHome(typedPath.get().strip())));
        } catch (java.nio.file.InvalidPathException e) {
          tell("not a valid path: " + typedPath.get());
        }
      }
      ImGui.sameLine();
      if (ImGui.button("Cancel")) {
        ImGui.closeCurrentPopup();
      }
      ImGui.endPopup();
    }
    drawHandIn();
    if (!conflicts.isEmpty() && !ImGui.isPopupOpen("Changed on disk")) {
      ImGui.openPopup("Changed on disk");
    }
    if (ImGui.beginPopupModal("Changed on disk", ImGuiWindowFlags.AlwaysAutoResize)) {
      Path file = conflicts.peek();
      ImGui.textUnformatted(file + " was changed outside RobotRun,");
      ImGui.textUnformatted("and the program was also edited here. Which version do you keep?");
      if (ImGui.button("Keep the window's version")) {
        actions.resolveConflict(conflicts.poll(), false);
        ImGui.closeCurrentPopup();
      }
      ImGui.sameLine();
      if (ImGui.button("Load the file's version")) {
        actions.resolveConflict(conflicts.poll(), true);
        ImGui.closeCurrentPopup();
      }
      ImGui.endPopup();
    }
    if (!messages.isEmpty() && !ImGui.isPopupOpen("RobotRun##message") && !ImGui.isPopupOpen("Changed on disk")) {
      ImGui.openPopup("RobotRun##message");
    }
    if (ImGui.beginPopupModal("RobotRun##message", ImGuiWindowFlags.AlwaysAutoResize)) {
      ImGui.pushTextWrapPos(ImGui.getFontSize() * 54);
      ImGui.textUnformatted(messages.isEmpty() ? "" : Txt.plain(messages.peek()));
      ImGui.popTextWrapPos();
      if (ImGui.button("OK") || ImGui.isKeyPressed(GLFW_KEY_ENTER)) {
        messages.poll();
        ImGui.closeCurrentPopup();
      }
      ImGui.endPopup();
    }
  }

  private void drawHandIn() {
    if (openHandIn) {
      ImGui.openPopup("Hand in");
      openHandIn = false;
      askReplace = false;
      handInError = "";
    }
    if (ImGui.beginPopupModal("Hand in", ImGuiWindowFlags.AlwaysAutoResize)) {
      ImGui.textUnformatted("Writes one .zip of this workspace (cell.json, programs/*.LS, manifest.json) for your instructor.");
      ImGui.setNextItemWidth(ImGui.getFontSize() * 31);
      ImGui.inputText("Your name", student);
      ImGui.setNextItemWidth(ImGui.getFontSize() * 31);
      ImGui.inputText("File", handInPath);
      ImGui.sameLine();
      if (ImGui.button("Choose...")) {
        if (dialogs.save("Zip archive", "zip", null, typedFileName(handInPath.get()))
            instanceof FileDialogs.Answer.Chosen c && !c.paths().isEmpty()) {
          handInPath.set(c.paths().get(0).toString());
        }
      }
      if (!handInError.isEmpty()) {
        ImGui.pushTextWrapPos(ImGui.getFontSize() * 49);
        Txt.colored(0.95f, 0.3f, 0.3f, 1f, handInError);
        ImGui.popTextWrapPos();
      }
      if (askReplace) {
        Txt.colored(0.95f, 0.7f, 0.2f, 1f, handInPath.get() + " exists.");
        if (ImGui.button("Replace it")) {
          finishHandIn(true);
        }
        ImGui.sameLine();
        if (ImGui.button("Keep it")) {
          askReplace = false;
        }
      } else if (ImGui.button("Hand in")) {
        if (handInPath.get().isBlank()) {
          handInError = "File: type the name of the .zip to write (or Choose...)";
        } else if (typedFileName(handInPath.get()) != null
            && java.nio.file.Files.exists(Path.of(expandHome(handInPath.get().strip())))) {
          askReplace = true;
        } else {
          finishHandIn(false);
        }
      }
      ImGui.sameLine();
      if (ImGui.button("Cancel")) {
        ImGui.closeCurrentPopup();
      }
      ImGui.endPopup();
    }
  }

  /** The file-name part of a typed path, "" when it has none, null when the text is no path on this system. */
  private static String typedFileName(String typed) {
    try {
      Path p = Path.of(expandHome(typed.strip())).getFileName();
      return p == null ? "" : p.toString();
    } catch (java.nio.file.InvalidPathException e) {
      return null;
    }
  }

  private void finishHandIn(boolean replace) {
    String m;
    try {
      m = actions.handIn(student.get(), Path.of(expandHome(handInPath.get().strip())), replace);
    } catch (java.nio.file.InvalidPathException e) {
      m = "not a valid path: " + handInPath.get();
    }
    askReplace = false;
    if (m.startsWith("handed in")) {
      ImGui.closeCurrentPopup();
      handInError = "";
      tell(m);
    } else {
      handInError = m;  // shown in the form, which stays open
    }
  }

  private static String expandHome(String p) {
    return p.startsWith("~/") ? System.getProperty("user.home") + p.substring(1) : p;
  }
}
