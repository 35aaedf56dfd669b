package org.robotrun.pendant;

import java.util.List;
import java.util.Objects;
import java.util.function.IntFunction;
import org.robotrun.program.Instruction;

/**
 * One piece of an instruction line on the EDIT screen: its text and, when the cursor may sit on
 * it, how it is edited (a choice list, typed entry, or both).
 */
public record Field(String text, Edit edit) {
  public Field {
    Objects.requireNonNull(text, "text");
  }

  /** Fixed text the cursor skips. */
  static Field fixed(String text) {
    return new Field(text, null);
  }

  /** Whether the cursor may sit on it. */
  public boolean editable() {
    return edit != null;
  }

  /** Applies typed text to the line, or says why it cannot. */
  @FunctionalInterface
  public interface Entry {
    Instruction apply(String text) throws ExprText.BadText;
  }

  /**
   * How a field is edited. {@code choices} (possibly empty) open with ENTER or [CHOICE] and
   * {@code choose} builds the new line from the chosen index; {@code entry} (possibly null)
   * takes typed text or keypad digits, starting from {@code initial}.
   */
  public record Edit(List<String> choices, IntFunction<Instruction> choose, String initial, Entry entry) {
    public Edit {
      choices = List.copyOf(choices);
      Objects.requireNonNull(initial, "initial");
    }

    static Edit entry(String initial, Entry entry) {
      return new Edit(List.of(), null, initial, entry);
    }

    static Edit choice(List<String> choices, IntFunction<Instruction> choose) {
      return new Edit(choices, choose, "", null);
    }

    static Edit both(List<String> choices, IntFunction<Instruction> choose, String initial, Entry entry) {
      return new Edit(choices, choose, initial, entry);
    }
  }
}
