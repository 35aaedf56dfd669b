package org.robotrun.pendant;

import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.function.Function;
import java.util.function.IntConsumer;

/**
 * A prompt that takes the keys until it closes: a choice list, a text or number entry, or a
 * YES/NO confirmation. PREV cancels any of them.
 */
sealed interface Modal {

  /**
   * A numbered choice list drawn over the body: UP/DOWN and ENTER, or a digit picks directly.
   */
  final class Choice implements Modal {
    final String title;
    final List<String> options;
    final IntConsumer onChoose;
    int cursor;

    Choice(String title, List<String> options, IntConsumer onChoose) {
      this.title = Objects.requireNonNull(title, "title");
      this.options = List.copyOf(options);
      this.onChoose = Objects.requireNonNull(onChoose, "onChoose");
    }
  }

  /**
   * Text or number entry on the prompt line. Typed text and keypad characters append;
   * BACKSPACE deletes; ENTER hands the text to {@code onEnter}, which answers an error for the
   * prompt line or empty. In letter mode F1..F5 enter letters pendant-style: each key cycles
   * through its group while pressed repeatedly, and another key accepts the letter.
   */
  final class Entry implements Modal {
    /** Letter groups on F1..F5 for pendant-style entry. */
    static final List<String> LETTER_GROUPS = List.of("ABCDEF", "GHIJKL", "MNOPQR", "STUVWX", "YZ_@*");

    final String prompt;
    final StringBuilder buffer;
    final boolean letters;
    final Function<String, Optional<String>> onEnter;
    /** The F-key group whose letter is still cycling (-1 for none). */
    int pendingGroup = -1;
    int pendingIndex;
    /** The buffer still holds the offered value: the first typed character replaces it. */
    boolean fresh;

    Entry(String prompt, String initial, boolean fresh, boolean letters, Function<String, Optional<String>> onEnter) {
      this.prompt = Objects.requireNonNull(prompt, "prompt");
      this.buffer = new StringBuilder(initial);
      this.fresh = fresh && !initial.isEmpty();
      this.letters = letters;
      this.onEnter = Objects.requireNonNull(onEnter, "onEnter");
    }

    /** F1..F5 (0..4) in letter mode. */
    void letterKey(int group) {
      clearIfFresh();
      String g = LETTER_GROUPS.get(group);
      if (pendingGroup == group && buffer.length() > 0) {
        pendingIndex = (pendingIndex + 1) % g.length();
        buffer.setCharAt(buffer.length() - 1, g.charAt(pendingIndex));
      } else {
        pendingGroup = group;
        pendingIndex = 0;
        buffer.append(g.charAt(0));
      }
    }

    /** Appends typed text (replacing an offered value). */
    void append(String text) {
      clearIfFresh();
      settle();
      buffer.append(text);
    }

    private void clearIfFresh() {
      if (fresh) {
        buffer.setLength(0);
        fresh = false;
      }
    }

    /** Accepts a cycling letter (any other key does). */
    void settle() {
      pendingGroup = -1;
    }
  }

  /** A YES (F4) / NO (F5) question on the prompt line. */
  final class Confirm implements Modal {
    final String question;
    final Runnable onYes;

    Confirm(String question, Runnable onYes) {
      this.question = Objects.requireNonNull(question, "question");
      this.onYes = Objects.requireNonNull(onYes, "onYes");
    }
  }
}
