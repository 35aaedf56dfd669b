package org.robotrun.ui;

import imgui.ImGui;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;
import org.robotrun.pendant.Pendant;

/**
 * The robot selector of a cell of several robots, as the GROUP switch of a multi-group pendant:
 * every robot keeps its own controller and pendant (screens, cursor, TP ENABLE, DEADMAN), and the
 * selector chooses which one the window's pendant panel, keyboard and operator panel drive. The
 * robots not selected go on running what they run. Keys held on the robot left (SHIFT, DEADMAN,
 * a jog key) are let go first, so no robot keeps jogging unseen. Drawn as a section of the left
 * column and as a Robots menu in the menu bar.
 */
public final class RobotSelector implements Supplier<Pendant>, Workbench.MenuContributor {
  /** The section title. */
  public static final String TITLE = "Robot selector";

  private final List<String> names;
  private final List<Pendant> pendants;
  private final List<Runnable> beforeSwitch = new ArrayList<>();
  private int selected;

  /** @param names robot names in cell order, one per pendant */
  public RobotSelector(List<String> names, List<Pendant> pendants) {
    if (names.size() != pendants.size() || names.isEmpty()) {
      throw new IllegalArgumentException("one pendant per robot: " + pendants.size() + " pendants, " + names.size() + " robots");
    }
    this.names = List.copyOf(names);
    this.pendants = List.copyOf(pendants);
  }

  /** Runs before every switch (the window releases the keys the keyboard and the mouse hold). */
  public void onBeforeSwitch(Runnable r) {
    beforeSwitch.add(r);
  }

  /** The selected robot's pendant. */
  @Override
  public Pendant get() {
    return pendants.get(selected);
  }

  /** Index of the selected robot in cell order. */
  public int selected() {
    return selected;
  }

  public String selectedName() {
    return names.get(selected);
  }

  public int size() {
    return names.size();
  }

  /** Selects robot {@code index} (cell order). */
  public void select(int index) {
    if (index < 0 || index >= names.size()) {
      throw new IllegalArgumentException("no robot " + (index + 1) + " (1.." + names.size() + ")");
    }
    if (index != selected) {
      beforeSwitch.forEach(Runnable::run);
      selected = index;
    }
  }

  /** A "Robots" menu in the menu bar (there at every window size, also when the left column is hidden). */
  @Override
  public void drawMenus() {
    if (ImGui.beginMenu("Robots")) {
      for (int i = 0; i < names.size(); i++) {
        if (ImGui.menuItem(names.get(i) + "##menurobot" + i, "", i == selected)) {
          select(i);
        }
      }
      ImGui.endMenu();
    }
  }

  /** One radio button per robot, with what its controller is doing. */
  public void drawContents() {
    for (int i = 0; i < names.size(); i++) {
      var st = pendants.get(i).control().status();
      String doing = st.program().isEmpty() ? "" : "  " + st.program() + " " + st.state();
      if (ImGui.radioButton(names.get(i) + doing + "##robot" + i, i == selected)) {
        select(i);
      }
    }
    ImGui.pushTextWrapPos(0);
    Txt.disabled("The pendant, keyboard and operator panel drive " + selectedName() + ".");
    ImGui.popTextWrapPos();
  }
}
