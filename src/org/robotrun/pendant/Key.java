package org.robotrun.pendant;

import java.util.Locale;
import java.util.Optional;

/**
 * The pendant's hard keys. Text entry has its own path ({@link Pendant#type(String)}); jog keys
 * carry their axis (1..6) and sign.
 */
public enum Key {
  F1("F1"), F2("F2"), F3("F3"), F4("F4"), F5("F5"),
  PREV("PREV"), NEXT("NEXT"), SHIFT("SHIFT"), DEADMAN("DEADMAN"), MENU("MENU"), SELECT("SELECT"), EDIT("EDIT"), DATA("DATA"),
  FCTN("FCTN"), DISP("DISP"), POSN("POSN"), IO("I/O"), STATUS("STATUS"), ITEM("ITEM"), ENTER("ENTER"),
  BACKSPACE("BACKSPACE"), UP("UP"), DOWN("DOWN"), LEFT("LEFT"), RIGHT("RIGHT"),
  D0("0"), D1("1"), D2("2"), D3("3"), D4("4"), D5("5"), D6("6"), D7("7"), D8("8"), D9("9"),
  DOT("."), MINUS("-"), COMMA(","),
  COORD("COORD"), STEP("STEP"), HOLD("HOLD"), FWD("FWD"), BWD("BWD"), RESET("RESET"),
  OVERRIDE_UP("+%"), OVERRIDE_DOWN("-%"),
  JOG_MINUS_1("-X/J1"), JOG_PLUS_1("+X/J1"), JOG_MINUS_2("-Y/J2"), JOG_PLUS_2("+Y/J2"),
  JOG_MINUS_3("-Z/J3"), JOG_PLUS_3("+Z/J3"), JOG_MINUS_4("-XR/J4"), JOG_PLUS_4("+XR/J4"),
  JOG_MINUS_5("-YR/J5"), JOG_PLUS_5("+YR/J5"), JOG_MINUS_6("-ZR/J6"), JOG_PLUS_6("+ZR/J6"),
  TOOL1("TOOL1"), TOOL2("TOOL2");

  private final String label;

  Key(String label) {
    this.label = label;
  }

  /** The key's legend as printed on the pendant and written in .keys scripts. */
  public String label() {
    return label;
  }

  /** Whether this is one of the twelve jog keys. */
  public boolean isJog() {
    return name().startsWith("JOG_");
  }

  /** Jog axis 1..6 (X/J1 … ZR/J6); only for jog keys. */
  public int jogAxis() {
    return name().charAt(name().length() - 1) - '0';
  }

  /** Jog direction +1 / -1; only for jog keys. */
  public int jogSign() {
    return name().startsWith("JOG_PLUS") ? 1 : -1;
  }

  /** The digit 0..9 of a digit key, or -1. */
  public int digit() {
    return name().length() == 2 && name().charAt(0) == 'D' ? name().charAt(1) - '0' : -1;
  }

  /** The character a keypad key enters in a number field (digits . - ,), if any. */
  public Optional<Character> keypadChar() {
    if (digit() >= 0) {
      return Optional.of((char) ('0' + digit()));
    }
    return switch (this) {
      case DOT -> Optional.of('.');
      case MINUS -> Optional.of('-');
      case COMMA -> Optional.of(',');
      default -> Optional.empty();
    };
  }

  /**
   * The key named {@code text} as scripts write it: its legend ({@code +X/J1}, {@code I/O},
   * {@code +%}), its enum name ({@code JOG_PLUS_1}), or a short jog alias ({@code +X},
   * {@code J1+}, {@code -J3}); case-insensitive.
   */
  public static Optional<Key> parse(String text) {
    String t = text.trim().toUpperCase(Locale.ROOT);
    for (Key k : values()) {
      if (k.label.equals(t) || k.name().equals(t)) {
        return Optional.of(k);
      }
    }
    switch (t) {
      case "IO" -> {
        return Optional.of(IO);
      }
      case "UP%", "OVERRIDE+" -> {
        return Optional.of(OVERRIDE_UP);
      }
      case "DOWN%", "OVERRIDE-" -> {
        return Optional.of(OVERRIDE_DOWN);
      }
      default -> { }
    }
    // jog aliases: +X, -ZR, +J1, J1+, -J6
    String[] cart = {"X", "Y", "Z", "XR", "YR", "ZR"};
    for (int axis = 1; axis <= 6; axis++) {
      for (int sign : new int[] {1, -1}) {
        String s = sign > 0 ? "+" : "-";
        if (t.equals(s + cart[axis - 1]) || t.equals(s + "J" + axis) || t.equals("J" + axis + s)) {
          return Optional.of(jog(axis, sign));
        }
      }
    }
    return Optional.empty();
  }

  /** The jog key for axis 1..6 and sign ±1. */
  public static Key jog(int axis, int sign) {
    return valueOf((sign > 0 ? "JOG_PLUS_" : "JOG_MINUS_") + axis);
  }

  /** The digit key 0..9. */
  public static Key digitKey(int d) {
    return valueOf("D" + d);
  }
}
