package org.robotrun.pendant;

import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.function.IntFunction;
import org.robotrun.program.Instruction;

/**
 * One piece of an instruction line on the EDIT screen: its text and, when the cursor may sit on
 * it, how it is edited (a choice list, typed entry, or both). Fixed text has no edit.
 */
public record Field(String text, Optional<Edit> edit) {
  public Field {
    Objects.requireNonNull(text, "text");
    Objects.requireNonNull(edit, "edit");
  }

  /** An editable field. */
  Field(String text, Edit edit) {
    this(text, Optional.of(edit));
  }

  /** Fixed text the cursor skips. */
  static Field fixed(String text) {
    return new Field(text, Optional.empty());
  }

  /** The same field building {@code wrap(line)} from each line its edit builds (an IF's action inside the IF). */
  Field mapped(java.util.function.UnaryOperator<Instruction> wrap) {
    if (edit.isEmpty()) {
      return this;
    }
    Edit e = edit.get();
    IntFunction<Instruction> choose = e.choices().isEmpty() ? e.choose() : k -> wrap.apply(e.choose().apply(k));
    Optional<Entry> entry = e.entry().map(en -> t -> wrap.apply(en.apply(t)));
    return new Field(text, Optional.of(new Edit(e.choices(), choose, e.initial(), entry)));
  }

  /** Whether the cursor may sit on it. */
  public boolean editable() {
    return edit.isPresent();
  }

  /** Applies typed text to the line, or says why it cannot. */
  @FunctionalInterface
  public interface Entry {
    Instruction apply(String text) throws ExprText.BadText;
  }

  /**
   * How a field is edited. {@code choices} (possibly empty) open with ENTER or [CHOICE] and
   * {@code choose} builds the new line from the chosen index; {@code entry}, when present, takes
   * typed text or keypad digits, offering {@code initial}.
   */
  public record Edit(List<String> choices, IntFunction<Instruction> choose, String initial, Optional<Entry> entry) {
    public Edit {
      choices = List.copyOf(choices);
      Objects.requireNonNull(choose, "choose");
      Objects.requireNonNull(initial, "initial");
      Objects.requireNonNull(entry, "entry");
    }

    private static final IntFunction<Instruction> NO_CHOICE = i -> {
      throw new IllegalStateException("this field has no choices");
    };

    static Edit entry(String initial, Entry entry) {
      return new Edit(List.of(), NO_CHOICE, initial, Optional.of(entry));
    }

    static Edit choice(List<String> choices, IntFunction<Instruction> choose) {
      return new Edit(choices, choose, "", Optional.empty());
    }

    /** Choices and entry; a null {@code entry} means choices only. */
    static Edit both(List<String> choices, IntFunction<Instruction> choose, String initial, Entry entry) {
      return new Edit(choices, choose, initial, Optional.ofNullable(entry));
    }
  }
}
