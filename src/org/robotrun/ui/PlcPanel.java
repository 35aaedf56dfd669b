package org.robotrun.ui;

import imgui.ImGui;
import imgui.type.ImBoolean;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.robotrun.program.IoKind;
import org.robotrun.sim.BgLogic;
import org.robotrun.sim.Controller;
import org.robotrun.sim.ExecutionStatus;
import org.robotrun.sim.Tasks;
import org.robotrun.sim.Uop;
import org.robotrun.world.ProductionSetup;

/**
 * The PLC panel: the cell PLC's side of the UOP signals, driven by hand. Each UI input is a
 * switch (START and PROD_START act when switched off again: their falling edge); each UO output
 * is a lamp, with the PLC sequence's step. Two more sections of the left column: the running tasks
 * with PAUSE, RESUME and ABORT ({@link #drawTasks}), and the BG Logic slots (the controller's MENU >
 * SETUP > BG Logic) with START and STOP ({@link #drawBgLogic}).
 */
public final class PlcPanel {
  /** The section title. */
  public static final String TITLE = PanelRules.Panel.PLC.title();

  private final java.util.function.Supplier<Controller> robot;
  private Controller controller;
  private final ImBoolean box = new ImBoolean();
  private int bgChoice;
  private String bgMessage = "";

  /** @param robot the controller the panel shows (the robot the selector chose) */
  public PlcPanel(java.util.function.Supplier<Controller> robot) {
    this.robot = robot;
  }

  /** The panel's controls, inside the section the workbench opened. */
  public void drawContents() {
    controller = robot.get();
    Uop u = controller.uop();
    Optional<ProductionSetup.Robot> setup = u.setup();
    if (!u.enabled()) {
      Txt.wrapped(setup.isEmpty() ? "UOP inputs are off: the scenario has no \"production\" setup for this robot "
          + "(docs/production.md). Outputs are still shown." : "UOP inputs are off (\"uop\": false).");
    } else {
      ProductionSetup.Robot s = setup.get();
      Txt.wrapped(String.format(Locale.ROOT, "%s, selection %s%s", s.remote() ? "Remote" : "Local (the PLC cannot start)",
          s.selection(), u.selectedProgram().isEmpty() ? "" : ", selected " + u.selectedProgram()));
      if (!s.plc().isEmpty()) {
        int step = u.plcStep();
        String note = step < s.plc().size() ? s.plc().get(step).note() : "done";
        Txt.wrapped(String.format(Locale.ROOT, "PLC sequence: step %d of %d: %s", Math.min(step + 1, s.plc().size()),
            s.plc().size(), note));
        if (ImGui.smallButton("Restart PLC")) {
          u.restartPlc();
        }
        if (ImGui.isItemHovered()) {
          Txt.tooltip("Every UI input OFF, the sequence from its first step (a PLC switched off and on)");
        }
      }
    }
    if (!u.lastRefusal().isEmpty()) {
      Txt.colored(1f, 0.55f, 0.45f, 1f, "Last start refused: " + u.lastRefusal());
    }
    ImGui.setNextItemOpen(setup.isPresent(), imgui.flag.ImGuiCond.Once);
    if (ImGui.treeNode("UI (PLC -> robot)##plcui")) {
      if (ImGui.beginTable("##uitable", columns())) {
        for (int i = 1; i <= 18; i++) {
          ImGui.tableNextColumn();
          box.set(u.ui(i));
          if (ImGui.checkbox(String.format(Locale.ROOT, "UI[%d] %s##ui%d", i, Uop.UI_NAMES.get(i), i), box)) {
            u.setUi(i, box.get());
          }
        }
        ImGui.endTable();
      }
      Txt.disabledWrapped("*IMSTP, *HOLD, *SFSPD stop when OFF. START and PROD_START act when switched OFF again.", false);
      ImGui.treePop();
    }
    ImGui.setNextItemOpen(setup.isPresent(), imgui.flag.ImGuiCond.Once);
    if (ImGui.treeNode("UO (robot -> PLC)##plcuo")) {
      if (ImGui.beginTable("##uotable", columns())) {
        for (int i = 1; i <= 20; i++) {
          ImGui.tableNextColumn();
          boolean on = u.uo(i);
          String text = String.format(Locale.ROOT, "%s UO[%d] %s", on ? "[ON ]" : "[off]", i, Uop.UO_NAMES.get(i));
          if (on) {
            Txt.colored(0.35f, 0.9f, 0.35f, 1f, text);
          } else {
            Txt.disabled(text);
          }
        }
        ImGui.endTable();
      }
      ImGui.treePop();
    }
  }

  /** Two columns of signals when the side panel is wide enough for their names, else one. */
  private static int columns() {
    return ImGui.getContentRegionAvailX() > 330 ? 2 : 1;
  }

  /** The running tasks with PAUSE, RESUME and ABORT: the "Tasks" section. */
  public void drawTasks() {
    controller = robot.get();
    ExecutionStatus main = controller.status();
    Txt.wrapped(String.format(Locale.ROOT, "main: %s line %d %s", main.program().isEmpty() ? "-" : main.program(),
        main.line(), main.state()));
    List<Tasks.Task> tasks = controller.tasks().list();
    if (tasks.isEmpty()) {
      Txt.disabled("no RUN tasks");
    }
    for (Tasks.Task t : tasks) {
      ExecutionStatus s = t.status();
      ImGui.textUnformatted(String.format(Locale.ROOT, "%s line %d %s%s", t.program(), s.line(), s.state(),
          t.holdsMotionGroup() ? " (group 1)" : ""));
      ImGui.sameLine();
      if (s.state() == ExecutionStatus.State.PAUSED) {
        if (ImGui.smallButton("RESUME##t" + t.program())) {
          controller.tasks().resume(t.program());
        }
      } else if (ImGui.smallButton("PAUSE##t" + t.program())) {
        controller.tasks().pause(t.program());
      }
      ImGui.sameLine();
      if (ImGui.smallButton("ABORT##t" + t.program())) {
        controller.tasks().abort(t.program());
      }
    }
  }

  /** The BG Logic slots with START, STOP and REMOVE, and the programs a slot takes: the "BG Logic" section. */
  /**
   * What BG Logic says when it offers no program: it points to "Not offered" only when that list
   * shows (with no program at all it pointed to a list that was not there), and says what a
   * background program is.
   *
   * @param anySlot whether a program is in a BG slot already
   * @param notOffered how many programs are listed under "Not offered"
   */
  static String noOfferHint(boolean anySlot, int notOffered) {
    String none = anySlot ? "No other program can run as BG Logic" : "No program can run as BG Logic";
    if (notOffered > 0) {
      return none + ": \"Not offered\" says why";
    }
    return anySlot ? none : "No programs yet. A BG Logic program has no motion group (DEFAULT_GROUP = *,*,*,*,*)";
  }

  public void drawBgLogic() {
    controller = robot.get();
    Txt.disabled(String.format(Locale.ROOT, "scan every %.0f ms, %d scans so far", controller.bgLogic().scanSec() * 1000,
        controller.bgLogic().scans()));
    for (BgLogic.Slot s : controller.bgLogic().slots()) {
      ImGui.textUnformatted(s.program() + (s.running() ? "  Running" : "  Stop"));
      ImGui.sameLine();
      if (ImGui.smallButton((s.running() ? "STOP##bg" : "START##bg") + s.program())) {
        bgMessage = controller.bgLogic().setRunning(s.program(), !s.running()).orElse("");
      }
      ImGui.sameLine();
      if (ImGui.smallButton("REMOVE##bg" + s.program())) {
        controller.bgLogic().remove(s.program());
      }
    }
    // only what the controller takes as background logic; the rest are listed with the reason
    BgLogic.Offer offer = controller.bgLogic().offer(controller.programNames());
    List<String> names = offer.programs();
    if (names.isEmpty()) {
      Txt.disabledWrapped(noOfferHint(!controller.bgLogic().slots().isEmpty(), offer.notOffered().size()), false);
    }
    if (!names.isEmpty()) {
      bgChoice = Math.max(0, Math.min(bgChoice, names.size() - 1));
      ImGui.setNextItemWidth(160);
      if (ImGui.beginCombo("##bgprog", names.get(bgChoice))) {
        for (int i = 0; i < names.size(); i++) {
          if (ImGui.selectable(names.get(i) + "##bgsel" + i, i == bgChoice)) {
            bgChoice = i;
          }
        }
        ImGui.endCombo();
      }
      ImGui.sameLine();
      if (ImGui.button("Add to BG")) {
        bgMessage = controller.bgLogic().add(names.get(bgChoice)).orElse(names.get(bgChoice) + " runs every scan");
      }
    }
    if (!offer.notOffered().isEmpty() && ImGui.treeNode("Not offered (" + offer.notOffered().size() + ")##bgwhy")) {
      for (String why : offer.notOffered()) {
        Txt.wrapped(why);
      }
      ImGui.treePop();
    }
    if (!bgMessage.isEmpty()) {
      Txt.wrapped(bgMessage);
    }
  }
}
