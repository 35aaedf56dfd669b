package org.robotrun.io;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.robotrun.program.Expr;
import org.robotrun.program.Index;
import org.robotrun.program.Instruction;
import org.robotrun.program.Item;
import org.robotrun.program.LabelRef;
import org.robotrun.program.LocalPosition;
import org.robotrun.program.Motion;

/**
 * What a lab's controller would refuse or treat differently in a program RobotRun reads, line by
 * line ({@code check --controller}): options a standard controller lacks (iRVision, Soft Float,
 * coordinated motion, the application tools), statements of a newer system than the one named,
 * and text longer than the controller keeps. The rows and their sources are in
 * docs/to-the-robot.md; where a row is RobotRun's reading rather than FANUC's documentation, the
 * message says "check your controller".
 */
public final class ControllerCompat {
  /** Item comments, program comments: what the pendant keeps (FANUC R-30iB Operator's Manual). */
  static final int MAX_COMMENT = 16;

  /** The controllers RobotRun can compare with, oldest first. */
  public enum Model {
    R_30IA("R-30iA"),
    R_30IB("R-30iB"),
    R_30IB_PLUS("R-30iB-Plus");

    private final String label;

    Model(String label) {
      this.label = label;
    }

    public String label() {
      return label;
    }

    /** The model named {@code text} (any case), if RobotRun knows it. */
    public static Optional<Model> of(String text) {
      for (Model m : values()) {
        if (m.label.equalsIgnoreCase(text.strip())) {
          return Optional.of(m);
        }
      }
      return Optional.empty();
    }
  }

  private ControllerCompat() {}

  /** The diagnostics for {@code r} on {@code model}: errors for what it refuses, warnings for what it treats differently. */
  public static List<Diagnostic> check(LsReadResult r, Model model) {
    List<Diagnostic> out = new ArrayList<>();
    String who = model.label() + ": ";
    if (r.program() == null) {
      return out;
    }
    if (r.program().comment().length() > MAX_COMMENT) {
      out.add(warn(r, 1, who + "the program comment is " + r.program().comment().length()
          + " characters; the pendant keeps " + MAX_COMMENT));
    }
    List<Instruction> lines = r.program().lines();
    for (int i = 0; i < lines.size(); i++) {
      int line = r.sourceLine(i + 1);
      Instruction in = lines.get(i);
      option(in).ifPresent(o -> out.add(error(r, line, who + "needs the " + o + " option, which a standard "
          + model.label() + " does not have (check the controller's option list: MENU > STATUS > Version ID)")));
      newer(in, model).ifPresent(n -> out.add(error(r, line, who + n + " is a statement of a newer system than "
          + model.label() + " (RobotRun's reading: check your controller's manual)")));
      List<String> comments = new ArrayList<>();
      comments(in, comments);
      for (String c : comments) {
        if (c.length() > MAX_COMMENT) {
          out.add(warn(r, line, who + "the comment '" + TerminalText.safe(c) + "' is " + c.length()
              + " characters; the controller keeps " + MAX_COMMENT));
        }
      }
    }
    for (LocalPosition p : r.program().positions().values()) {
      if (p.comment().length() > MAX_COMMENT) {
        out.add(warn(r, 1, who + "the comment of P[" + p.number() + "] is " + p.comment().length()
            + " characters; the controller keeps " + MAX_COMMENT));
      }
    }
    return out;
  }

  private static Diagnostic error(LsReadResult r, int line, String message) {
    return Diagnostic.of(r.file(), line, 1, Diagnostic.Severity.ERROR, Diagnostic.Kind.STYLE, message);
  }

  private static Diagnostic warn(LsReadResult r, int line, String message) {
    return Diagnostic.of(r.file(), line, 1, Diagnostic.Severity.WARNING, Diagnostic.Kind.STYLE, message);
  }

  /** The controller option a line needs beyond a standard controller, if any. */
  static Optional<String> option(Instruction in) {
    if (usesVision(in)) {
      return Optional.of("iRVision");
    }
    String kind = switch (in) {
      case Instruction.Unsupported u -> u.what();
      case Instruction.Move m -> m.options().stream()
          .map(o -> o instanceof Motion.RawOption raw ? raw.what() : "")
          .filter(w -> !w.isEmpty()).findFirst().orElse("");
      default -> "";
    };
    String text = in instanceof Instruction.Unsupported u ? u.text().toUpperCase(Locale.ROOT) : "";
    String k = kind.toLowerCase(Locale.ROOT);
    if (k.contains("irvision") || k.contains("vision") || text.startsWith("VISION")) {
      return Optional.of("iRVision");
    }
    if (k.contains("softfloat")) {
      return Optional.of("Soft Float");
    }
    if (k.contains("coordinated motion")) {
      return Optional.of("Coordinated Motion");
    }
    if (k.contains("arc welding") || k.contains("seam tracking")) {
      return Optional.of("ArcTool (arc welding)");
    }
    if (k.contains("spot welding")) {
      return Optional.of("SpotTool (spot welding)");
    }
    if (k.contains("palletizing")) {
      return Optional.of("PalletTool (palletizing)");
    }
    if (k.contains("arithmetic function")) {
      return Optional.of("math function");
    }
    if (k.contains("err_num")) {
      return Optional.of("error recovery");
    }
    return Optional.empty();
  }

  /** An iRVision statement, a VR[] read or a motion with VOFFSET,VR[i]. */
  private static boolean usesVision(Instruction in) {
    return switch (in) {
      case Instruction.VisionRunFind v -> true;
      case Instruction.VisionGetOffset v -> true;
      case Instruction.VisionGetNFound v -> true;
      case Instruction.AssignFromVr v -> true;
      case Instruction.AssignPosReg a -> a.source() instanceof Instruction.FromVisionRegister;
      case Instruction.Move m -> m.options().stream().anyMatch(Motion.VisionOffset.class::isInstance);
      default -> false;
    };
  }

  /** A statement the named controller's system software does not have yet, if this is one. */
  static Optional<String> newer(Instruction in, Model model) {
    if (in instanceof Instruction.Unsupported u && model != Model.R_30IB_PLUS) {
      String w = u.what();
      if (w.startsWith("named CALL arguments") || w.startsWith("CALL through a string register")
          || w.startsWith("TIMER[i] set to a value")) {
        return Optional.of(w);
      }
    }
    if (model == Model.R_30IA && usesStrings(in)) {
      return Optional.of("a string register SR[] or string function");
    }
    return Optional.empty();
  }

  private static boolean usesStrings(Instruction in) {
    if (in instanceof Instruction.AssignString) {
      return true;
    }
    List<Expr> exprs = new ArrayList<>();
    switch (in) {
      case Instruction.AssignRegister a -> exprs.add(a.value());
      case Instruction.If f -> exprs.add(f.condition());
      case Instruction.IfThen f -> exprs.add(f.condition());
      case Instruction.WaitCondition w -> exprs.add(w.condition());
      case Instruction.Call c -> exprs.addAll(c.args());
      default -> { }
    }
    return exprs.stream().anyMatch(ControllerCompat::stringy);
  }

  private static boolean stringy(Expr e) {
    return switch (e) {
      case Expr.StringReg s -> true;
      case Expr.StringFunc f -> true;
      case Expr.StringConst s -> true;
      case Expr.Unary u -> stringy(u.operand());
      case Expr.Binary b -> stringy(b.left()) || stringy(b.right());
      case Expr.Group g -> stringy(g.inner());
      default -> false;
    };
  }

  /** The item and label comments of a line. */
  private static void comments(Instruction in, List<String> out) {
    switch (in) {
      case Instruction.AssignRegister a -> {
        item(a.register(), out);
        expr(a.value(), out);
      }
      case Instruction.Label l -> out.add(l.comment());
      case Instruction.Jump j -> label(j.label(), out);
      case Instruction.If f -> {
        expr(f.condition(), out);
        if (f.branch() instanceof Instruction.Jump j) {
          label(j.label(), out);
        }
      }
      case Instruction.IfThen f -> expr(f.condition(), out);
      case Instruction.WaitCondition w -> expr(w.condition(), out);
      case Instruction.SetIo s -> {
        item(s.port(), out);
        expr(s.value(), out);
      }
      case Instruction.Move m -> {
        if (m.target() instanceof Motion.Local l) {
          out.add(l.comment());
        } else if (m.target() instanceof Motion.Register pr) {
          item(pr.register(), out);
        }
      }
      default -> { }
    }
  }

  private static void item(Item i, List<String> out) {
    out.add(i.comment());
    if (i.index() instanceof Index.Indirect r) {
      out.add(r.comment());
    }
  }

  private static void label(LabelRef l, List<String> out) {
    out.add(l.comment());
  }

  private static void expr(Expr e, List<String> out) {
    switch (e) {
      case Expr.Register r -> item(r.register(), out);
      case Expr.Io io -> {
        // "DI[2:ON :PART IN]": the state the controller lists before an I/O comment is not the comment
        out.add(io.port().comment().replaceFirst("^(ON|OFF)\\s*:", ""));
      }
      case Expr.PosElement p -> item(p.register(), out);
      case Expr.Unary u -> expr(u.operand(), out);
      case Expr.Binary b -> {
        expr(b.left(), out);
        expr(b.right(), out);
      }
      case Expr.Group g -> expr(g.inner(), out);
      default -> { }
    }
  }
}
