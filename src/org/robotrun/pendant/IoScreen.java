package org.robotrun.pendant;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.robotrun.program.IoKind;

/**
 * I/O: DI/DO/RI/RO/GI/GO lists. Outputs are switched by the operator (F4 ON / F5 OFF, a number
 * for GO); inputs may be forced the same way to simulate a sensor, and the screen says so.
 */
final class IoScreen implements Screen {
  private static final List<IoKind> KINDS = List.of(IoKind.DI, IoKind.DO, IoKind.RI, IoKind.RO, IoKind.GI, IoKind.GO);
  /** Largest group I/O value: a 16-bit group. */
  private static final int GROUP_MAX = 65535;
  private IoKind kind = IoKind.DO;
  private final int[] cursor = new int[IoKind.values().length];

  @Override
  public String title(Pendant p) {
    return "I/O " + kind + (kind.writable() ? "  (outputs)" : "  (inputs: values set here are simulated)");
  }

  @Override
  public List<String> body(Pendant p) {
    List<String> rows = new ArrayList<>();
    int cur = cursor[kind.ordinal()];
    int top = Math.max(0, Math.min(cur - Lcd.BODY_ROWS / 2, p.control().registers().ioSize(kind) - Lcd.BODY_ROWS));
    for (int i = top; i < p.control().registers().ioSize(kind) && rows.size() < Lcd.BODY_ROWS; i++) {
      int n = i + 1;
      String v = kind.group() ? Integer.toString(p.control().registers().value(kind, n))
          : p.control().registers().bit(kind, n) ? "ON" : "OFF";
      rows.add((i == cur ? ">" : " ") + String.format(Locale.ROOT, "%s[%2d]  %s", kind, n, i == cur ? "{" + v + "}" : v));
    }
    return rows;
  }

  @Override
  public List<String> functionKeys(Pendant p) {
    return List.of("[TYPE]", "", "", kind.group() ? "" : "ON", kind.group() ? "" : "OFF");
  }

  @Override
  public void key(Pendant p, Key k) {
    int t = kind.ordinal();
    int n = cursor[t] + 1;
    switch (k) {
      case UP -> cursor[t] = Math.max(0, cursor[t] - 1);
      case DOWN -> cursor[t] = Math.min(p.control().registers().ioSize(kind) - 1, cursor[t] + 1);
      case F1 -> p.choose("I/O TYPE", KINDS.stream().map(IoKind::name).toList(), KINDS.indexOf(kind), i -> kind = KINDS.get(i));
      case F4, F5 -> {
        if (kind.group()) {
          p.message("Group I/O: type a number and ENTER");
          return;
        }
        p.control().registers().setBit(kind, n, k == Key.F4);
        p.message(kind + "[" + n + "]=" + (k == Key.F4 ? "ON" : "OFF") + (kind.writable() ? "" : " (simulated input)"));
      }
      case ITEM -> p.entry("Port number:", "", false, s -> {
        Optional<Integer> v = Pendant.parseInt(s, 1, p.control().registers().ioSize(kind));
        if (v.isEmpty()) {
          return Optional.of("Port must be 1.." + p.control().registers().ioSize(kind) + ", got '" + s.trim() + "'");
        }
        cursor[t] = v.get() - 1;
        return Optional.empty();
      });
      default -> {
        if (kind.group() && (k.keypadChar().isPresent() || k == Key.ENTER)) {
          // The key that opens the entry is its first character (a keypad digit), kept as typed.
          groupValueEntry(p, k.keypadChar().map(String::valueOf).orElse(null));
        } else if (k == Key.ENTER) {
          boolean on = !p.control().registers().bit(kind, n);
          p.control().registers().setBit(kind, n, on);
        } else {
          p.message("I/O: F1 [TYPE], F4 ON / F5 OFF (ENTER toggles), a number for GI/GO");
        }
      }
    }
  }

  @Override
  public void text(Pendant p, String s) {
    if (kind.group()) {
      groupValueEntry(p, s);
    } else {
      Screen.super.text(p, s);
    }
  }

  /** The value entry of the group port under the cursor; {@code typed} starts it, or null for none. */
  private void groupValueEntry(Pendant p, String typed) {
    IoKind k = kind;
    int n = cursor[k.ordinal()] + 1;
    p.entryOrTyped(k + "[" + n + "] value:", typed, "", false, s -> {
      int v;
      try {
        v = NumberEntry.wholeWithin(k + "[" + n + "]", s, 0, GROUP_MAX);
      } catch (ExprText.BadText e) {
        return Optional.of(e.getMessage());
      }
      p.control().registers().setValue(k, n, v);
      p.message(k + "[" + n + "]=" + v + (k.writable() ? "" : " (simulated input)"));
      return Optional.empty();
    });
  }
}
