package org.robotrun.io;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.robotrun.program.Index;
import org.robotrun.program.Instruction;
import org.robotrun.program.LabelRef;
import org.robotrun.program.Motion;
import org.robotrun.program.Program;

/**
 * Checks that need the whole program rather than one line: P[] used but not in /POS, labels
 * defined twice or jumped to but never defined, IF/ELSE/ENDIF, FOR/ENDFOR and SELECT lines that
 * do not match up, and (given the set of known programs) CALLs to programs that do not exist.
 */
final class LsProgramChecks {
  private LsProgramChecks() {}

  /** All program-level checks except unknown CALL targets. */
  static List<Diagnostic> check(String file, Program program, List<Integer> sourceLines) {
    List<Diagnostic> out = new ArrayList<>();
    List<Instruction> lines = program.lines();
    Map<Integer, Integer> labels = new HashMap<>();
    for (int i = 0; i < lines.size(); i++) {
      if (lines.get(i) instanceof Instruction.Label l) {
        Integer first = labels.putIfAbsent(l.number(), i);
        if (first != null) {
          out.add(Diagnostic.error(file, sourceLines.get(i),
              "LBL[" + l.number() + "] is defined twice (first on line " + sourceLines.get(first) + ")"));
        }
      }
    }
    for (int i = 0; i < lines.size(); i++) {
      int line = sourceLines.get(i);
      for (int p : localPositionsUsed(lines.get(i))) {
        if (program.position(p).isEmpty()) {
          out.add(Diagnostic.error(file, line, "P[" + p + "] is used but /POS has no P[" + p + "]"));
        }
      }
      for (LabelRef target : labelTargets(lines.get(i))) {
        if (target.index() instanceof Index.Direct d && !labels.containsKey(d.value())) {
          out.add(Diagnostic.error(file, line, "LBL[" + d.value() + "] is not defined in this program"));
        }
      }
    }
    blockStructure(file, lines, sourceLines, out);
    return out;
  }

  /** A diagnostic for each CALL whose target is not among {@code known} (nor the program itself). */
  static List<Diagnostic> unknownCalls(LsReadResult r, Set<String> known) {
    Set<String> names = new HashSet<>();
    for (String k : known) {
      names.add(k.toUpperCase(Locale.ROOT));
    }
    names.add(r.program().name().toUpperCase(Locale.ROOT));
    List<Diagnostic> out = new ArrayList<>();
    List<Instruction> lines = r.program().lines();
    for (int i = 0; i < lines.size(); i++) {
      Optional<Instruction.Call> call = callIn(lines.get(i));
      if (call.isPresent() && !names.contains(call.get().program().toUpperCase(Locale.ROOT))) {
        out.add(Diagnostic.error(r.file(), r.sourceLine(i + 1),
            "CALL " + call.get().program() + ": no program named " + call.get().program() + " is known"));
      }
    }
    return out;
  }

  private static Optional<Instruction.Call> callIn(Instruction in) {
    Instruction.Branch b = switch (in) {
      case Instruction.Call c -> c;
      case Instruction.If f -> f.branch();
      case Instruction.Select s -> s.branch();
      case Instruction.SelectCase s -> s.branch();
      case Instruction.SelectElse s -> s.branch();
      default -> null;
    };
    return b instanceof Instruction.Call c ? Optional.of(c) : Optional.empty();
  }

  private static List<Integer> localPositionsUsed(Instruction in) {
    List<Integer> out = new ArrayList<>(2);
    if (in instanceof Instruction.Move m) {
      if (m.target() instanceof Motion.Local l) {
        out.add(l.number());
      }
      m.circularEnd().ifPresent(t -> {
        if (t instanceof Motion.Local l) {
          out.add(l.number());
        }
      });
    } else if (in instanceof Instruction.AssignPosReg a && a.source() instanceof Instruction.FromLocal f) {
      out.add(f.number());
    }
    return out;
  }

  private static List<LabelRef> labelTargets(Instruction in) {
    List<LabelRef> out = new ArrayList<>(1);
    switch (in) {
      case Instruction.Jump j -> out.add(j.label());
      case Instruction.If f -> jumpOf(f.branch(), out);
      case Instruction.Select s -> jumpOf(s.branch(), out);
      case Instruction.SelectCase s -> jumpOf(s.branch(), out);
      case Instruction.SelectElse s -> jumpOf(s.branch(), out);
      case Instruction.WaitCondition w -> w.timeoutLabel().ifPresent(out::add);
      case Instruction.Move m -> {
        for (Motion.Option o : m.options()) {
          if (o instanceof Motion.Skip s) {
            out.add(s.label());
          }
        }
      }
      default -> {
        // no label used
      }
    }
    return out;
  }

  private static void jumpOf(Instruction.Branch b, List<LabelRef> out) {
    if (b instanceof Instruction.Jump j) {
      out.add(j.label());
    }
  }

  /** IF...THEN/ELSE/ENDIF and FOR/ENDFOR nest; SELECT case lines follow a SELECT line. */
  private static void blockStructure(String file, List<Instruction> lines, List<Integer> src, List<Diagnostic> out) {
    // Each open block: its kind ('I' = IF THEN, 'E' = its ELSE part, 'F' = FOR) and line index.
    Deque<int[]> open = new ArrayDeque<>();
    for (int i = 0; i < lines.size(); i++) {
      Instruction in = lines.get(i);
      int line = src.get(i);
      switch (in) {
        case Instruction.IfThen t -> open.push(new int[] {'I', i});
        case Instruction.For f -> open.push(new int[] {'F', i});
        case Instruction.Else e -> {
          if (open.isEmpty() || open.peek()[0] != 'I') {
            out.add(Diagnostic.error(file, line, "ELSE without an open IF ... THEN"
                + innermost(open, src)));
          } else {
            open.peek()[0] = 'E';
          }
        }
        case Instruction.EndIf e -> {
          if (open.isEmpty() || (open.peek()[0] != 'I' && open.peek()[0] != 'E')) {
            out.add(Diagnostic.error(file, line, "ENDIF without an open IF ... THEN" + innermost(open, src)));
          } else {
            open.pop();
          }
        }
        case Instruction.EndFor e -> {
          if (open.isEmpty() || open.peek()[0] != 'F') {
            out.add(Diagnostic.error(file, line, "ENDFOR without an open FOR" + innermost(open, src)));
          } else {
            open.pop();
          }
        }
        case Instruction.SelectCase c -> selectFollows(file, lines, i, line, "=value", out);
        case Instruction.SelectElse c -> selectFollows(file, lines, i, line, "ELSE,", out);
        default -> {
          // not a block statement
        }
      }
    }
    while (!open.isEmpty()) {
      int[] b = open.pop();
      String what = b[0] == 'F' ? "FOR has no ENDFOR" : "IF ... THEN has no ENDIF";
      out.add(Diagnostic.error(file, src.get(b[1]), what));
    }
  }

  private static String innermost(Deque<int[]> open, List<Integer> src) {
    if (open.isEmpty()) {
      return "";
    }
    int[] b = open.peek();
    return " (the innermost open block is the " + (b[0] == 'F' ? "FOR" : "IF") + " on line " + src.get(b[1]) + ")";
  }

  private static void selectFollows(String file, List<Instruction> lines, int i, int line, String what, List<Diagnostic> out) {
    Instruction prev = i > 0 ? lines.get(i - 1) : null;
    if (!(prev instanceof Instruction.Select || prev instanceof Instruction.SelectCase)) {
      out.add(Diagnostic.error(file, line, "SELECT case '" + what + "' must follow a SELECT line or another case"));
    }
  }
}
