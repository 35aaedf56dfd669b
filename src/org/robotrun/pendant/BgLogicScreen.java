package org.robotrun.pendant;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.robotrun.control.RobotControl;
import org.robotrun.control.RobotControl.BgSlot;
import org.robotrun.control.RobotControl.Result;

/**
 * SETUP BG Logic: the background logic slots, each a program without a motion group that runs
 * from start to end every scan. F1 ADD (program name), F2 START, F3 STOP, F4 REMOVE; the
 * controller refuses a program a BG slot cannot run, with its reason. docs/production.md.
 */
final class BgLogicScreen implements Screen {
  private int cursor;

  @Override
  public String title(Pendant p) {
    return "SETUP BG Logic";
  }

  @Override
  public List<String> body(Pendant p) {
    List<BgSlot> slots = p.control().bgSlots();
    List<String> rows = new ArrayList<>();
    rows.add("   No. Program           Status");
    if (slots.isEmpty()) {
      rows.add("  (no BG Logic: F1 ADD puts a program in a slot)");
      return rows;
    }
    cursor = Math.max(0, Math.min(cursor, slots.size() - 1));
    for (int i = 0; i < slots.size() && rows.size() < Lcd.BODY_ROWS; i++) {
      BgSlot s = slots.get(i);
      rows.add(String.format(Locale.ROOT, "%s %3d %-17s %s", i == cursor ? ">" : " ", i + 1, s.program(),
          s.running() ? "Running" : "Stop"));
    }
    return rows;
  }

  @Override
  public List<String> functionKeys(Pendant p) {
    return List.of("ADD", "START", "STOP", "REMOVE", "");
  }

  @Override
  public void key(Pendant p, Key k) {
    List<BgSlot> slots = p.control().bgSlots();
    switch (k) {
      case UP -> cursor = Math.max(0, cursor - 1);
      case DOWN -> cursor = Math.min(Math.max(0, slots.size() - 1), cursor + 1);
      case F1 -> p.entry("BG program:", "", true, name -> {
        String n = name.strip().toUpperCase(Locale.ROOT);
        Result r = p.control().addBg(n);
        return switch (r) {
          case Result.Ok ok -> {
            p.message(n + " runs every scan");
            yield Optional.empty();
          }
          case Result.Refused no -> Optional.of(no.reason());
        };
      });
      case F2, F3, F4 -> {
        if (slots.isEmpty()) {
          p.message("No BG Logic slot in use: F1 ADD");
          return;
        }
        BgSlot s = slots.get(Math.max(0, Math.min(cursor, slots.size() - 1)));
        Result r = switch (k) {
          case F2 -> p.control().runBg(s.program(), true);
          case F3 -> p.control().runBg(s.program(), false);
          default -> p.control().removeBg(s.program());
        };
        p.message(switch (r) {
          case Result.Ok ok -> s.program() + (k == Key.F2 ? " started" : k == Key.F3 ? " stopped" : " removed");
          case Result.Refused no -> no.reason();
        });
      }
      default -> p.message("UP/DOWN choose a slot; F1 ADD, F2 START, F3 STOP, F4 REMOVE");
    }
  }
}
