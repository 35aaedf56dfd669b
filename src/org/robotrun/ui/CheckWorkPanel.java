package org.robotrun.ui;

import imgui.ImGui;
import imgui.flag.ImGuiCond;
import imgui.flag.ImGuiWindowFlags;
import imgui.type.ImBoolean;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import org.robotrun.grade.CheckResult;
import org.robotrun.grade.GradeResult;
import org.robotrun.grade.Grader;
import org.robotrun.math.Transform;
import org.robotrun.program.Instruction.FrameKind;
import org.robotrun.program.Position;
import org.robotrun.program.Program;
import org.robotrun.program.Registers;
import org.robotrun.sim.Controller;
import org.robotrun.sim.FrameTable;

/**
 * The "Check" menu and the "Check my work" window: runs the task's visible checks on the
 * programs, frames and registers the student has now, in fresh simulations on a background
 * thread (the window's own simulation is not touched), and shows the same feedback the grader
 * gives. Hidden checks stay hidden. Joins the menu bar as a {@link Workbench.MenuContributor}.
 */
public final class CheckWorkPanel implements Workbench.MenuContributor {
  private final Grader grader;
  private final List<Controller> controllers;
  private CompletableFuture<GradeResult> running;
  private GradeResult last;
  private String error = "";
  private final ImBoolean open = new ImBoolean(false);
  private java.util.function.Consumer<GradeResult> onResult = r -> { };

  /** Told every result of Check my work (the Labs menu remembers the last score). */
  public void onResult(java.util.function.Consumer<GradeResult> listener) {
    this.onResult = listener;
  }

  /**
   * @param controllers the window's robots, first robot first: the first robot's programs, frames
   *     and registers are checked, and in a cell of several robots each other robot's programs and
   *     registers (matched by name with the task's robots)
   */
  public CheckWorkPanel(Grader grader, List<Controller> controllers) {
    this.grader = grader;
    this.controllers = List.copyOf(controllers);
  }

  /** @param controller the window's only robot */
  public CheckWorkPanel(Grader grader, Controller controller) {
    this(grader, List.of(controller));
  }

  /** The Check menu (on the GUI thread, which owns the controller). */
  @Override
  public void drawMenus() {
    if (ImGui.beginMenu("Check")) {
      if (ImGui.menuItem("Check my work", "", false, running == null)) {
        open.set(true);
        start();
      }
      ImGui.endMenu();
    }
  }

  /** The results window when open, after the other windows. */
  @Override
  public void drawPopups() {
    if (open.get()) {
      draw();
    }
  }

  private void draw() {
    ImGui.setNextWindowPos(ImGui.getIO().getDisplaySizeX() * 0.25f, 60, ImGuiCond.FirstUseEver);
    ImGui.setNextWindowSize(ImGui.getFontSize() * 40, ImGui.getIO().getDisplaySizeY() * 0.7f, ImGuiCond.FirstUseEver);
    ImGui.setNextWindowBgAlpha(0.95f);
    if (ImGui.begin("Check my work", open, ImGuiWindowFlags.NoCollapse)) {
      ImGui.pushTextWrapPos(0);
      ImGui.textUnformatted(grader.task().title());
      boolean busy = running != null && !running.isDone();
      if (busy) {
        Txt.disabled("checking...");
      } else if (ImGui.button("Check my work")) {
        start();
      }
      if (running != null && running.isDone()) {
        try {
          last = running.join();
          error = "";
          onResult.accept(last);
        } catch (RuntimeException e) {
          error = "The check failed: " + e.getMessage();
        }
        running = null;
      }
      if (!error.isEmpty()) {
        ImGui.textUnformatted(Txt.plain(error));
      }
      if (last != null) {
        ImGui.textUnformatted(String.format(Locale.ROOT, "%s of %s points", fmt(last.score()), fmt(last.maxScore())));
        for (CheckResult c : last.checks()) {
          Txt.colored(c.passed() ? 0.3f : 0.95f, c.passed() ? 0.8f : 0.35f, c.passed() ? 0.4f : 0.3f, 1f,
              (c.passed() ? "PASS " : "FAIL ") + fmt(c.score()) + "/" + fmt(c.maxScore()) + "  " + c.name());
          ImGui.indent();
          Txt.disabled(c.feedback());
          ImGui.unindent();
        }
      }
      ImGui.popTextWrapPos();
    }
    ImGui.end();
  }

  /** Copies what the student has now (on this thread) and grades the copy on another. */
  private void start() {
    Controller controller = controllers.get(0);
    List<Program> programs = programsOf(controller);
    FrameTable frames = controller.frames();
    Map<Integer, Transform> tool = new HashMap<>();
    Map<Integer, Transform> user = new HashMap<>();
    for (int n = 1; n <= FrameTable.COUNT; n++) {
      tool.put(n, frames.transform(FrameKind.TOOL, n));
      user.put(n, frames.transform(FrameKind.USER, n));
    }
    Map<Integer, Double> registers = new HashMap<>();
    Registers regs = controller.registers();
    for (int i = 1; i <= Registers.R_COUNT; i++) {
      registers.put(i, regs.number(i));
    }
    Map<Integer, Position> positions = new HashMap<>();
    for (int i = 1; i <= Registers.PR_COUNT; i++) {
      positions.put(i, regs.position(i));
    }
    Map<String, List<Program>> otherPrograms = new HashMap<>();
    Map<String, Grader.RobotRegisters> otherRegisters = new HashMap<>();
    for (Controller c : controllers.subList(1, controllers.size())) {
      otherPrograms.put(c.name(), programsOf(c));
      otherRegisters.put(c.name(), new Grader.RobotRegisters(numbers(c.registers()), positions(c.registers())));
    }
    running = CompletableFuture.supplyAsync(() -> grader.checkMyWork(programs, tool, user, registers, positions,
        otherPrograms, otherRegisters));
    // the idle window sleeps: wake it to show the result
    running.whenComplete((r, e) -> SimulatorWindow.wakeFromAnyThread());
  }

  private static List<Program> programsOf(Controller c) {
    return c.programNames().stream().map(n -> c.program(n).orElseThrow()).toList();
  }

  private static Map<Integer, Double> numbers(Registers regs) {
    Map<Integer, Double> out = new HashMap<>();
    for (int i = 1; i <= Registers.R_COUNT; i++) {
      out.put(i, regs.number(i));
    }
    return out;
  }

  private static Map<Integer, Position> positions(Registers regs) {
    Map<Integer, Position> out = new HashMap<>();
    for (int i = 1; i <= Registers.PR_COUNT; i++) {
      out.put(i, regs.position(i));
    }
    return out;
  }

  private static String fmt(double d) {
    return d == Math.rint(d) ? Long.toString((long) d) : String.format(Locale.ROOT, "%.1f", d);
  }
}
