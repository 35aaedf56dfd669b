package org.robotrun.io;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.Predicate;
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
      Instruction in = lines.get(i);
      if (in instanceof Instruction.Move m) {
        requirePosition(program, m.target(), file, line, out);
        if (m.circularEnd().isPresent()) {
          requirePosition(program, m.circularEnd().get(), file, line, out);
        }
      } else if (in instanceof Instruction.AssignPosReg a && a.source() instanceof Instruction.FromLocal f) {
        requirePosition(program, new Motion.Local(f.number(), f.comment()), file, line, out);
      }
      for (LabelRef target : labelTargets(lines.get(i))) {
        if (target.index() instanceof Index.Direct d && !labels.containsKey(d.value())) {
          // A controller loads such a program; the jump alarms (INTP-310 label not found) when it runs.
          out.add(Diagnostic.of(file, line, 0, Diagnostic.Severity.WARNING, Diagnostic.Kind.REFERENCE,
              "LBL[" + d.value() + "] is not defined in this program: the jump alarms when it runs"));
        }
      }
    }
    blockStructure(file, lines, sourceLines, out);
    return out;
  }

  /** A diagnostic for each CALL whose target is not {@code known} (the program itself always is). */
  static List<Diagnostic> unknownCalls(LsReadResult r, Predicate<String> known) {
    return unknownCalls(r, known, Map.of());
  }

  /**
   * As {@link #unknownCalls(LsReadResult, Predicate)}, with a macro table (macro name as
   * {@code InterpreterSettings.macroKey} keys it → program): a macro of the table must name a
   * known program; a macro of several words outside it is reported as not in the table.
   */
  static List<Diagnostic> unknownCalls(LsReadResult r, Predicate<String> known, Map<String, String> macros) {
    String self = r.program().name();
    List<Diagnostic> out = new ArrayList<>();
    List<Instruction> lines = r.program().lines();
    for (int i = 0; i < lines.size(); i++) {
      Optional<Instruction.Call> call = callIn(lines.get(i));
      if (call.isPresent()) {
        String target = call.get().program();
        String viaTable = lines.get(i) instanceof Instruction.MacroCall
            ? macros.get(org.robotrun.program.InterpreterSettings.macroKey(target)) : null;
        if (viaTable != null) {
          if (!viaTable.equalsIgnoreCase(self) && !known.test(viaTable)) {
            out.add(Diagnostic.error(r.file(), r.sourceLine(i + 1), "macro " + target + " runs " + viaTable
                + " (macro table): no program named " + viaTable + " is known"));
          }
        } else if (lines.get(i) instanceof Instruction.MacroCall && target.contains(" ")) {
          // A macro of several words names no program: the controller's macro table says what it runs.
          out.add(Diagnostic.error(r.file(), r.sourceLine(i + 1), "macro " + target + ": not in the macro table (a "
              + "robot's \"macros\" in the scenario define it; the line alarms when it runs without one)"));
        } else if (!target.equalsIgnoreCase(self) && !known.test(target)) {
          out.add(Diagnostic.error(r.file(), r.sourceLine(i + 1),
              (lines.get(i) instanceof Instruction.MacroCall ? "macro "
                  : lines.get(i) instanceof Instruction.Monitor ? "MONITOR "
                  : lines.get(i) instanceof Instruction.Run ? "RUN " : "CALL ") + target + ": no program named "
                  + target + " is known"));
        }
      }
    }
    return out;
  }

  /** The CALL a line makes, directly or as the branch of an IF or SELECT line. */
  private static Optional<Instruction.Call> callIn(Instruction in) {
    Optional<Instruction.Branch> b = branchOf(in);
    if (in instanceof Instruction.Call c) {
      return Optional.of(c);
    }
    if (in instanceof Instruction.MacroCall m) {
      return Optional.of(new Instruction.Call(m.name(), List.of()));
    }
    if (in instanceof Instruction.When w) {
      return Optional.of(w.action());
    }
    if (in instanceof Instruction.Monitor mo) {
      return Optional.of(new Instruction.Call(mo.program(), List.of()));
    }
    if (in instanceof Instruction.Move mv) {
      // TB/TA/DB ...,CALL PROG
      for (org.robotrun.program.Motion.Option o : mv.options()) {
        if (o instanceof org.robotrun.program.Motion.TimedAction t && t.action() instanceof Instruction.Call c) {
          return Optional.of(c);
        }
      }
    }
    if (in instanceof Instruction.Run r) {
      // RUN names a program as CALL does (it starts it as a task)
      return Optional.of(new Instruction.Call(r.program(), r.args()));
    }
    return b.filter(x -> x instanceof Instruction.Call).map(x -> (Instruction.Call) x);
  }

  /** The branch of an IF or SELECT line. */
  private static Optional<Instruction.Branch> branchOf(Instruction in) {
    if (in instanceof Instruction.If f) {
      return Optional.of(f.branch());
    } else if (in instanceof Instruction.Select s) {
      return Optional.of(s.branch());
    } else if (in instanceof Instruction.SelectCase s) {
      return Optional.of(s.branch());
    } else if (in instanceof Instruction.SelectElse s) {
      return Optional.of(s.branch());
    }
    return Optional.empty();
  }

  private static void requirePosition(Program program, Motion.Target t, String file, int line, List<Diagnostic> out) {
    if (t instanceof Motion.Local l && !program.positions().containsKey(l.number())) {
      // A controller loads it and shows the position uninitialised; the line alarms when it runs.
      out.add(Diagnostic.of(file, line, 0, Diagnostic.Severity.WARNING, Diagnostic.Kind.REFERENCE,
          "P[" + l.number() + "] is used but /POS has no P[" + l.number()
              + "]: the position is uninitialised and the line alarms when it runs"));
    }
  }

  /** Labels a line may jump to: JMP, IF/SELECT branches, WAIT ... TIMEOUT, VISION GET_OFFSET and motion Skip. */
  private static List<LabelRef> labelTargets(Instruction in) {
    List<LabelRef> out = new ArrayList<>(1);
    if (in instanceof Instruction.Jump j) {
      out.add(j.label());
    } else if (in instanceof Instruction.WaitCondition w) {
      w.timeoutLabel().ifPresent(out::add);
    } else if (in instanceof Instruction.VisionGetOffset v) {
      out.add(v.label());
    } else if (in instanceof Instruction.Move m) {
      for (Motion.Option o : m.options()) {
        if (o instanceof Motion.Skip s) {
          out.add(s.label());
        }
      }
    }
    branchOf(in).ifPresent(b -> {
      if (b instanceof Instruction.Jump j) {
        out.add(j.label());
      }
    });
    return out;
  }

  /** The kinds of block a line can open. */
  private enum Block {
    IF_THEN,
    ELSE_PART,
    FOR
  }

  /** A block opened on program line {@code index} (0-based) and not yet closed. */
  private record Open(Block kind, int index) {}

  /** IF...THEN/ELSE/ENDIF and FOR/ENDFOR nest; SELECT case lines follow a SELECT line. */
  private static void blockStructure(String file, List<Instruction> lines, List<Integer> src, List<Diagnostic> out) {
    Deque<Open> open = new ArrayDeque<>();
    for (int i = 0; i < lines.size(); i++) {
      Instruction in = lines.get(i);
      int line = src.get(i);
      Block top = open.isEmpty() ? null : open.peek().kind();
      if (in instanceof Instruction.IfThen || opensIfThen(in)) {
        open.push(new Open(Block.IF_THEN, i));
      } else if (in instanceof Instruction.For || opensFor(in)) {
        open.push(new Open(Block.FOR, i));
      } else if (in instanceof Instruction.Else) {
        if (top == Block.IF_THEN) {
          open.push(new Open(Block.ELSE_PART, open.pop().index()));
        } else {
          out.add(Diagnostic.error(file, line, "ELSE without an open IF ... THEN" + innermost(open, src)));
        }
      } else if (in instanceof Instruction.EndIf) {
        if (top == Block.IF_THEN || top == Block.ELSE_PART) {
          open.pop();
        } else {
          out.add(Diagnostic.error(file, line, "ENDIF without an open IF ... THEN" + innermost(open, src)));
        }
      } else if (in instanceof Instruction.EndFor) {
        if (top == Block.FOR) {
          open.pop();
        } else {
          out.add(Diagnostic.error(file, line, "ENDFOR without an open FOR" + innermost(open, src)));
        }
      } else if (in instanceof Instruction.SelectCase) {
        selectFollows(file, lines, i, line, "=value", out);
      } else if (in instanceof Instruction.SelectElse) {
        selectFollows(file, lines, i, line, "ELSE,", out);
      }
    }
    while (!open.isEmpty()) {
      Open b = open.pop();
      String what = b.kind() == Block.FOR ? "FOR has no ENDFOR" : "IF ... THEN has no ENDIF";
      out.add(Diagnostic.error(file, src.get(b.index()), what));
    }
  }

  /** An IF ... THEN line kept as not supported (its condition): it still opens a block its ENDIF closes. */
  static boolean opensIfThen(Instruction in) {
    return in instanceof Instruction.Unsupported u && u.opensIfThen();
  }

  /** A FOR line kept as not supported: it still opens a block its ENDFOR closes. */
  static boolean opensFor(Instruction in) {
    return in instanceof Instruction.Unsupported u && u.opensFor();
  }

  private static String innermost(Deque<Open> open, List<Integer> src) {
    if (open.isEmpty()) {
      return "";
    }
    Open b = open.peek();
    return " (the innermost open block is the " + (b.kind() == Block.FOR ? "FOR" : "IF") + " on line " + src.get(b.index()) + ")";
  }

  private static void selectFollows(String file, List<Instruction> lines, int i, int line, String what, List<Diagnostic> out) {
    Instruction prev = i > 0 ? lines.get(i - 1) : null;
    if (!(prev instanceof Instruction.Select || prev instanceof Instruction.SelectCase)) {
      out.add(Diagnostic.error(file, line, "SELECT case '" + what + "' must follow a SELECT line or another case"));
    }
  }
}
