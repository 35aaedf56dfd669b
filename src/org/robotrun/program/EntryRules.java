package org.robotrun.program;

import java.util.EnumSet;
import java.util.Optional;
import java.util.Set;

/**
 * The controller's entry rules for expressions (issue 13; docs/tp-language.md, "Entry rules"):
 * on a line without parentheses, {@code +}/{@code -} are not mixed with {@code *}, {@code /},
 * {@code DIV}, {@code MOD}, and {@code AND} is not mixed with {@code OR}. An expression in
 * parentheses is a mixed-logic expression, where any mix is allowed with the usual precedence.
 * The pendant refuses such an entry with this reason; {@code check} warns about it in a file.
 */
public final class EntryRules {
  private EntryRules() {}

  private static final Set<Expr.BinaryOp> ADDITIVE = EnumSet.of(Expr.BinaryOp.ADD, Expr.BinaryOp.SUB);
  private static final Set<Expr.BinaryOp> MULTIPLICATIVE =
      EnumSet.of(Expr.BinaryOp.MUL, Expr.BinaryOp.DIVIDE, Expr.BinaryOp.DIV, Expr.BinaryOp.MOD);

  /**
   * Most conditions joined by AND/OR in one standard (unparenthesised) instruction: five, as
   * FANUC America's advanced TP course states ("in standard logic a maximum of five logical
   * conditions can be evaluated").
   */
  public static final int MAX_STANDARD_CONDITIONS = 5;

  /**
   * Most conditions in one mixed-logic instruction: twenty, the same course's upper bound ("in
   * Mixed Logic up to twenty conditions per statement are allowed depending on the data type
   * used"); RobotRun applies the bound to every data type.
   */
  public static final int MAX_MIXED_CONDITIONS = 20;

  /** Why a controller would refuse {@code e} as typed, or empty when it takes it. */
  public static Optional<String> refusal(Expr e) {
    if (hasGroup(e, 0)) {
      // mixed logic: parentheses allow any mix, up to twenty conditions
      int n = conditions(e, 0);
      if (n > MAX_MIXED_CONDITIONS) {
        return Optional.of("the controller takes at most " + MAX_MIXED_CONDITIONS
            + " conditions in one mixed-logic instruction, this one has " + n + ": split it over several lines");
      }
      return Optional.empty();
    }
    int n = conditions(e, 0);
    if (n > MAX_STANDARD_CONDITIONS) {
      return Optional.of("the controller takes at most " + MAX_STANDARD_CONDITIONS
          + " conditions joined by AND/OR on a line without parentheses, this one has " + n
          + ": put the condition in parentheses (mixed logic) or split it");
    }
    Set<Expr.BinaryOp> ops = EnumSet.noneOf(Expr.BinaryOp.class);
    collect(e, ops, 0);
    if (ops.stream().anyMatch(ADDITIVE::contains) && ops.stream().anyMatch(MULTIPLICATIVE::contains)) {
      return Optional.of("the controller does not mix + or - with *, /, DIV or MOD on a line without parentheses: "
          + "put the expression in parentheses (mixed logic)");
    }
    if (ops.contains(Expr.BinaryOp.AND) && ops.contains(Expr.BinaryOp.OR)) {
      return Optional.of("the controller does not mix AND with OR on a line without parentheses: "
          + "put the condition in parentheses (mixed logic)");
    }
    return Optional.empty();
  }

  /** The operands of the AND/OR tree of {@code e} (1 for an expression without AND/OR). */
  private static int conditions(Expr e, int depth) {
    if (depth > TpLimits.MAX_OPERATORS) {
      return 1;
    }
    return switch (e) {
      case Expr.Group g -> conditions(g.inner(), depth + 1);
      case Expr.Unary u when u.op() == Expr.UnaryOp.NOT -> conditions(u.operand(), depth + 1);
      case Expr.Binary b when b.op() == Expr.BinaryOp.AND || b.op() == Expr.BinaryOp.OR ->
          conditions(b.left(), depth + 1) + conditions(b.right(), depth + 1);
      default -> 1;
    };
  }

  private static boolean hasGroup(Expr e, int depth) {
    if (depth > TpLimits.MAX_OPERATORS) {
      return false;
    }
    return switch (e) {
      case Expr.Group g -> true;
      case Expr.Unary u -> hasGroup(u.operand(), depth + 1);
      case Expr.Binary b -> hasGroup(b.left(), depth + 1) || hasGroup(b.right(), depth + 1);
      default -> false;
    };
  }

  private static void collect(Expr e, Set<Expr.BinaryOp> ops, int depth) {
    if (depth > TpLimits.MAX_OPERATORS) {
      return;
    }
    switch (e) {
      case Expr.Unary u -> collect(u.operand(), ops, depth + 1);
      case Expr.Binary b -> {
        ops.add(b.op());
        collect(b.left(), ops, depth + 1);
        collect(b.right(), ops, depth + 1);
      }
      default -> { }
    }
  }
}
