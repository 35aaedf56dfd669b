package org.robotrun.pendant;

import java.util.Locale;
import java.util.Objects;
import org.robotrun.program.Expr;
import org.robotrun.program.Index;
import org.robotrun.program.IoKind;
import org.robotrun.program.Item;
import org.robotrun.program.TpStatementParser;
import org.robotrun.program.TpSyntaxError;

/**
 * Expressions and bracketed items as the operator types them into a field ({@code R[1:COUNT]+1},
 * {@code (DI[1]=ON AND R[2]<>0)}), parsed by the TP grammar's one parser with the pendant's entry
 * checks. They are shown by the one printer of TP text, {@link org.robotrun.program.TpText}.
 */
public final class ExprText {
  private ExprText() {}

  /** Why typed text is not an expression: the message names the column and what was expected. */
  public static final class BadText extends Exception {
    private final boolean namesField;

    BadText(String message) {
      this(message, false);
    }

    /** {@code namesField}: the message starts with the field's name, so it needs no "Bad value" in front. */
    BadText(String message, boolean namesField) {
      super(message);
      this.namesField = namesField;
    }

    /** The text for the prompt line (one line, the field named). */
    String promptText() {
      return namesField ? getMessage() : "Bad value: " + getMessage();
    }
  }

  // ---- numbers on the pendant's screens (TP text itself is program.TpText's) --------------

  /** A real the shortest way that reads back the same ({@code 2.5}, {@code 3.0}). */
  public static String real(double v) {
    if (v == Math.rint(v) && Math.abs(v) < 1e9) {
      return String.format(Locale.ROOT, "%.1f", v);
    }
    return java.math.BigDecimal.valueOf(v).stripTrailingZeros().toPlainString();
  }

  /** A number without needless decimals ({@code 100}, {@code 0.5}). */
  public static String plain(double v) {
    if (v == Math.rint(v) && Math.abs(v) < 1e9) {
      return Long.toString((long) v);
    }
    return java.math.BigDecimal.valueOf(v).stripTrailingZeros().toPlainString();
  }

  // ---- parsing -------------------------------------------------------------------------------

  // Typed text is parsed by the TP grammar's one parser (program.TpStatementParser), so a field
  // accepts exactly what a .LS line may hold; the pendant adds only its entry checks (an index
  // outside its table, the controller's entry rules), which it refuses at once.

  /** Parses a typed expression ({@code R[2]+1}, {@code (DI[1]=ON AND R[3]>2)}). */
  public static Expr parse(String text) throws BadText {
    Expr e;
    try {
      e = TpStatementParser.expressionText(Objects.requireNonNull(text, "text"));
    } catch (TpSyntaxError x) {
      throw bad(x);
    }
    return checked(e);
  }

  /** {@code e} when the pendant takes it as typed: every index within its table, the controller's entry rules. */
  static Expr checked(Expr e) throws BadText {
    checkRanges(e, 0);
    // The controller's entry rules (program.EntryRules): refused here as the pendant does.
    java.util.Optional<String> refused = org.robotrun.program.EntryRules.refusal(e);
    if (refused.isPresent()) {
      String r = refused.get();
      throw new BadText(Character.toUpperCase(r.charAt(0)) + r.substring(1));
    }
    return e;
  }

  /** Parses {@code 5} or {@code R[2]} (an index or "n | R[i]" operand). */
  public static Index parseIndex(String text) throws BadText {
    try {
      return TpStatementParser.indexText(Objects.requireNonNull(text, "text"));
    } catch (TpSyntaxError x) {
      throw bad(x);
    }
  }

  /** Parses an item of the given kind: {@code R[3]}, {@code R[3:COUNT]}, or just {@code 3}. */
  public static Item parseItem(String kind, String text) throws BadText {
    String t = text.trim();
    Item item;
    try {
      item = !t.isEmpty() && Character.isDigit(t.charAt(0))
          ? new Item(TpStatementParser.indexText(t), "")
          : TpStatementParser.itemText(kind, t);
    } catch (TpSyntaxError x) {
      throw bad(x);
    }
    checkRange(kind, item.index());
    return item;
  }

  private static BadText bad(TpSyntaxError x) {
    return new BadText("column " + x.column() + ": " + x.getMessage());
  }

  /** Every direct index in {@code e} within its table (the parser bounds the depth). */
  private static void checkRanges(Expr e, int depth) throws BadText {
    if (depth > org.robotrun.program.TpLimits.MAX_OPERATORS) {
      return;
    }
    switch (e) {
      case Expr.Register r -> checkRange("R", r.register().index());
      case Expr.PosElement p -> checkRange("PR", p.register().index());
      case Expr.Io io -> checkRange(io.kind().name(), io.port().index());
      case Expr.Timer t -> checkRange("TIMER", t.timer().index());
      case Expr.StringReg r -> checkRange("SR", r.register().index());
      case Expr.StringFunc f -> {
        for (Expr a : f.args()) {
          checkRanges(a, depth + 1);
        }
      }
      case Expr.Arg a -> {
        if (a.index() instanceof Index.Indirect) {
          checkRange("AR", a.index());
        }
      }
      case Expr.Unary u -> checkRanges(u.operand(), depth + 1);
      case Expr.Binary b -> {
        checkRanges(b.left(), depth + 1);
        checkRanges(b.right(), depth + 1);
      }
      case Expr.Group g -> checkRanges(g.inner(), depth + 1);
      default -> { }
    }
  }

  /** Highest index of each table (Registers' sizes), for entry checks. */
  private static int size(String kind) {
    return switch (kind) {
      case "R" -> org.robotrun.program.Registers.R_COUNT;
      case "PR" -> org.robotrun.program.Registers.PR_COUNT;
      case "TIMER" -> org.robotrun.program.Registers.TIMER_COUNT;
      case "SR" -> org.robotrun.program.Registers.SR_COUNT;
      // The controller's I/O sizes are configured per cell; beyond them the line alarms when it runs.
      default -> java.util.Arrays.stream(IoKind.values()).anyMatch(k -> k.name().equals(kind))
          ? org.robotrun.program.IoRanges.MAX_SIZE : Integer.MAX_VALUE;
    };
  }

  /** A direct index outside its table is refused at entry (the controller would alarm at run time). */
  private static void checkRange(String kind, Index i) throws BadText {
    int n = switch (i) {
      case Index.Direct d -> d.value();
      case Index.Indirect r -> r.register();
      case Index.ViaArg a -> a.arg();
    };
    String table = i instanceof Index.Indirect ? "R" : i instanceof Index.ViaArg ? "AR" : kind;
    if (n < 1 || n > size(table)) {
      throw new BadText(table + "[" + n + "]: index out of range (1.." + size(table) + ")");
    }
  }
}
