package org.robotrun.pendant;

import java.util.ArrayList;
import java.util.Collections;
import java.util.Comparator;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.robotrun.pendant.ExprText.BadText;
import org.robotrun.program.Instruction;
import org.robotrun.program.LocalPosition;
import org.robotrun.program.Motion;
import org.robotrun.program.Program;

/**
 * The editor's line operations as pure functions on an immutable {@link Program}: insert,
 * delete, paste (as is, new position numbers, reverse), replace, renumber. The EDIT screen
 * decides where; these decide what the program becomes. Line numbers are 1-based.
 */
final class ProgramEdits {
  private ProgramEdits() {}

  /** How PASTE places the clipboard. */
  enum PasteMode {
    /** The lines as copied, the same P[] numbers. */
    AS_IS,
    /** Each pasted motion gets new P[] numbers with copies of the positions. */
    NEW_POSITIONS,
    /** The lines in reverse order (a path run backward), the same P[] numbers. */
    REVERSE
  }

  /** What REPLACE did: the program, how many fields changed and how many refused the new text. */
  record Replaced(Program program, int replaced, int refused) {}

  static Program with(Program prog, List<Instruction> lines, Map<Integer, LocalPosition> positions) {
    return prog.withBody(lines, positions);
  }

  static Program replaceLine(Program prog, int n, Instruction in) {
    List<Instruction> lines = new ArrayList<>(prog.lines());
    lines.set(n - 1, in);
    return with(prog, lines, prog.positions());
  }

  /**
   * Inserts {@code add} before line {@code at} (at most one past the end); a blank line at
   * {@code at} is replaced, as the controller fills a blank line it inserts into.
   */
  static Program insert(Program prog, int at, List<Instruction> add, Map<Integer, LocalPosition> newPositions) {
    List<Instruction> lines = new ArrayList<>(prog.lines());
    int idx = Math.min(at - 1, lines.size());
    if (idx < lines.size() && lines.get(idx) instanceof Instruction.Blank) {
      lines.remove(idx);
    }
    lines.addAll(idx, add);
    Map<Integer, LocalPosition> pos = new LinkedHashMap<>(prog.positions());
    pos.putAll(newPositions);
    return with(prog, lines, pos);
  }

  /** {@code count} blank lines before line {@code at}. */
  static Program insertBlanks(Program prog, int at, int count) {
    List<Instruction> lines = new ArrayList<>(prog.lines());
    lines.addAll(Math.min(at - 1, lines.size()), Collections.nCopies(count, new Instruction.Blank()));
    return with(prog, lines, prog.positions());
  }

  /** Deletes lines {@code from}..{@code to} (the positions stay: other lines may use them). */
  static Program delete(Program prog, int from, int to) {
    List<Instruction> lines = new ArrayList<>(prog.lines());
    lines.subList(from - 1, to).clear();
    return with(prog, lines, prog.positions());
  }

  /** Pastes {@code clipboard} before line {@code at}. */
  static Program paste(Program prog, int at, List<Instruction> clipboard, PasteMode mode) {
    List<Instruction> add = new ArrayList<>(clipboard);
    Map<Integer, LocalPosition> newPos = new HashMap<>();
    switch (mode) {
      case AS_IS -> { }
      case REVERSE -> Collections.reverse(add);
      case NEW_POSITIONS -> {
        int next = nextPositionNumber(prog);
        for (int i = 0; i < add.size(); i++) {
          if (add.get(i) instanceof Instruction.Move m) {
            Motion.Target t = m.target();
            Optional<Motion.Target> end = m.circularEnd();
            if (t instanceof Motion.Local l) {
              copyPosition(prog, l.number(), next, newPos);
              t = new Motion.Local(next++, l.comment());
            }
            if (end.isPresent() && end.get() instanceof Motion.Local l) {
              copyPosition(prog, l.number(), next, newPos);
              end = Optional.of(new Motion.Local(next++, l.comment()));
            }
            add.set(i, new Instruction.Move(m.type(), t, end, m.speed(), m.termination(), m.options()));
          }
        }
      }
    }
    List<Instruction> lines = new ArrayList<>(prog.lines());
    lines.addAll(Math.min(at - 1, lines.size()), add);
    Map<Integer, LocalPosition> pos = new LinkedHashMap<>(prog.positions());
    pos.putAll(newPos);
    return with(prog, lines, pos);
  }

  private static void copyPosition(Program prog, int from, int to, Map<Integer, LocalPosition> out) {
    prog.position(from).ifPresent(lp -> out.put(to, new LocalPosition(to, lp.comment(), lp.userFrame(),
        lp.toolFrame(), lp.position())));
  }

  /** One more than the highest P[] number the program uses or holds. */
  static int nextPositionNumber(Program prog) {
    int max = 0;
    for (int k : prog.positions().keySet()) {
      max = Math.max(max, k);
    }
    for (Instruction in : prog.lines()) {
      if (in instanceof Instruction.Move m) {
        for (Motion.Target t : targets(m)) {
          max = Math.max(max, t instanceof Motion.Local l ? l.number() : 0);
        }
      }
    }
    return max + 1;
  }

  /**
   * Replaces {@code from} by {@code to} in every editable field, field by field, through the
   * field's own entry (so the result is valid TP or the field is left alone and counted refused).
   */
  static Replaced replaceAll(Program prog, String from, String to, List<String> programs) {
    return replaceAll(prog, from, to, programs, TpLine.DEFAULT_MAX_MM_PER_SEC);
  }

  /** As above for a robot whose maximum TCP speed is {@code maxMmPerSec} (mm/s). */
  static Replaced replaceAll(Program prog, String from, String to, List<String> programs, double maxMmPerSec) {
    List<Instruction> lines = new ArrayList<>(prog.lines());
    int replaced = 0;
    int refused = 0;
    for (int n = 0; n < lines.size(); n++) {
      Program view = with(prog, lines, prog.positions());
      List<Field> fs = TpLine.fields(lines.get(n), view, programs, maxMmPerSec);
      for (int f = 0; f < fs.size(); f++) {
        Field fd = fs.get(f);
        Optional<Field.Edit> edit = fd.edit();
        if (edit.isEmpty() || edit.get().entry().isEmpty() || !fd.text().contains(from)) {
          continue;
        }
        Optional<Instruction> changed = Optional.empty();
        // the field as shown (R[3]) or as its entry offers it (3)
        for (String candidate : List.of(fd.text().replace(from, to), edit.get().initial().replace(from, to))) {
          try {
            changed = Optional.of(edit.get().entry().get().apply(candidate));
            break;
          } catch (BadText e) {
            // try the next form of the field's text
          }
        }
        if (changed.isEmpty()) {
          refused++;
        } else {
          replaced++;
          lines.set(n, changed.get());
          fs = TpLine.fields(changed.get(), view, programs, maxMmPerSec);
        }
      }
    }
    return new Replaced(with(prog, lines, prog.positions()), replaced, refused);
  }

  /** Renumbers P[] 1, 2, 3… in the order lines use them; unused positions follow. */
  static Program renumber(Program prog) {
    Map<Integer, Integer> map = new LinkedHashMap<>();
    for (Instruction in : prog.lines()) {
      if (in instanceof Instruction.Move m) {
        for (Motion.Target t : targets(m)) {
          if (t instanceof Motion.Local l) {
            map.putIfAbsent(l.number(), map.size() + 1);
          }
        }
      } else if (in instanceof Instruction.AssignPosReg a && a.source() instanceof Instruction.FromLocal l) {
        map.putIfAbsent(l.number(), map.size() + 1);
      }
    }
    for (int k : prog.positions().keySet()) {
      map.putIfAbsent(k, map.size() + 1);
    }
    List<Instruction> lines = new ArrayList<>();
    for (Instruction in : prog.lines()) {
      lines.add(switch (in) {
        case Instruction.Move m -> new Instruction.Move(m.type(), renumbered(m.target(), map),
            m.circularEnd().map(t -> renumbered(t, map)), m.speed(), m.termination(), m.options());
        case Instruction.AssignPosReg a when a.source() instanceof Instruction.FromLocal l ->
            new Instruction.AssignPosReg(a.register(), new Instruction.FromLocal(map.get(l.number()), l.comment()));
        default -> in;
      });
    }
    Map<Integer, LocalPosition> pos = new LinkedHashMap<>();
    prog.positions().values().stream().sorted(Comparator.comparing(lp -> map.get(lp.number())))
        .forEach(lp -> {
          int n = map.get(lp.number());
          pos.put(n, new LocalPosition(n, lp.comment(), lp.userFrame(), lp.toolFrame(), lp.position()));
        });
    return with(prog, lines, pos);
  }

  private static List<Motion.Target> targets(Instruction.Move m) {
    List<Motion.Target> t = new ArrayList<>();
    t.add(m.target());
    m.circularEnd().ifPresent(t::add);
    return t;
  }

  private static Motion.Target renumbered(Motion.Target t, Map<Integer, Integer> map) {
    return t instanceof Motion.Local l ? new Motion.Local(map.get(l.number()), l.comment()) : t;
  }
}
