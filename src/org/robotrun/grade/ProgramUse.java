package org.robotrun.grade;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.robotrun.program.Index;
import org.robotrun.program.Instruction;
import org.robotrun.program.Motion;
import org.robotrun.program.Program;

/** What the program text uses, for {@link Check.ProgramUse}: read from the parsed programs. */
final class ProgramUse {
  private ProgramUse() {}

  /** Why the check fails, or empty when it passes. All the submission's programs count. */
  static Optional<String> evaluate(Check.ProgramUse u, List<Program> programs, String main) {
    if (programs.isEmpty()) {
      return Optional.of("no program could be read, so nothing to look at");
    }
    Map<Check.Feature, String> where = new HashMap<>();
    int motions = 0;
    for (Program p : programs) {
      motions += scan(p, where);
    }
    List<String> problems = new ArrayList<>();
    for (Check.Feature f : u.requires()) {
      if (!where.containsKey(f)) {
        problems.add("the programs do not use " + f.words());
      }
    }
    for (Check.Feature f : u.forbids()) {
      if (where.containsKey(f)) {
        problems.add(where.get(f) + " uses " + f.words() + ", which this task does not allow");
      }
    }
    if (u.maxMotionLines().isPresent() && motions > u.maxMotionLines().getAsInt()) {
      problems.add(motions + " motion lines (allowed " + u.maxMotionLines().getAsInt() + ")");
    }
    return problems.isEmpty() ? Optional.empty() : Optional.of(String.join("; ", problems));
  }

  /** Words for a passed check. */
  static String describe(Check.ProgramUse u) {
    List<String> parts = new ArrayList<>();
    u.requires().forEach(f -> parts.add("uses " + f.words()));
    u.forbids().forEach(f -> parts.add("does not use " + f.words()));
    u.maxMotionLines().ifPresent(n -> parts.add("at most " + n + " motion lines"));
    return parts.isEmpty() ? "nothing to check" : String.join(", ", parts);
  }

  /** Records the first line using each feature ("PICK line 7"); returns the motion line count. */
  static int scan(Program p, Map<Check.Feature, String> where) {
    Map<Integer, Integer> labelLine = new HashMap<>();
    List<Instruction> lines = p.lines();
    for (int i = 0; i < lines.size(); i++) {
      if (lines.get(i) instanceof Instruction.Label l) {
        labelLine.putIfAbsent(l.number(), i + 1);
      }
    }
    int motions = 0;
    for (int i = 0; i < lines.size(); i++) {
      int line = i + 1;
      Set<Check.Feature> found = EnumSet.noneOf(Check.Feature.class);
      Instruction ins = lines.get(i);
      switch (ins) {
        case Instruction.Move m -> {
          motions++;
          found.add(switch (m.type()) {
            case J -> Check.Feature.JOINT_MOTION;
            case L -> Check.Feature.LINEAR_MOTION;
            case C, A -> Check.Feature.CIRCULAR_MOTION;
          });
          if (m.termination() instanceof Motion.Fine) {
            found.add(Check.Feature.FINE);
          } else {
            found.add(Check.Feature.CNT);
          }
          for (Motion.Option o : m.options()) {
            if (o instanceof Motion.OffsetPr) {
              found.add(Check.Feature.OFFSET_PR);
            } else if (o instanceof Motion.ToolOffsetPr) {
              found.add(Check.Feature.TOOL_OFFSET_PR);
            } else if (o instanceof Motion.VisionOffset) {
              found.add(Check.Feature.VOFFSET);
            }
          }
          if (m.target() instanceof Motion.Register || m.circularEnd().filter(Motion.Register.class::isInstance).isPresent()) {
            found.add(Check.Feature.PR_TARGET);
          }
        }
        case Instruction.For f -> found.add(Check.Feature.FOR);
        case Instruction.Run r -> found.add(Check.Feature.RUN);
        case Instruction.Jump j -> branch(j, line, labelLine, found);
        case Instruction.Call c -> found.add(Check.Feature.CALL);
        case Instruction.If f -> {
          found.add(Check.Feature.IF);
          branch(f.branch(), line, labelLine, found);
        }
        case Instruction.IfThen f -> found.add(Check.Feature.IF);
        case Instruction.Select s -> {
          found.add(Check.Feature.SELECT);
          branch(s.branch(), line, labelLine, found);
        }
        case Instruction.SelectCase s -> branch(s.branch(), line, labelLine, found);
        case Instruction.SelectElse s -> branch(s.branch(), line, labelLine, found);
        case Instruction.WaitTime w -> found.add(Check.Feature.WAIT);
        case Instruction.WaitCondition w -> found.add(Check.Feature.WAIT);
        default -> { }
      }
      for (Check.Feature f : found) {
        where.putIfAbsent(f, p.name() + " line " + line);
      }
    }
    return motions;
  }

  private static void branch(Instruction.Branch b, int line, Map<Integer, Integer> labelLine, Set<Check.Feature> found) {
    switch (b) {
      case Instruction.Jump j -> {
        // A jump through a register (LBL[R[1]]) cannot be judged from the text; only direct labels count.
        if (j.label().index() instanceof Index.Direct d) {
          Integer target = labelLine.get(d.value());
          if (target != null && target < line) {
            found.add(Check.Feature.JMP_BACKWARD);
          }
        }
      }
      case Instruction.Call c -> found.add(Check.Feature.CALL);
    }
  }
}
