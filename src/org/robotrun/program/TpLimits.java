package org.robotrun.program;

/**
 * Limits of the TP statement language, shared by the .LS reader, the pendant's text entry and
 * the writer, so that what one accepts the others accept too, and no recursive walk of an
 * expression can overflow the stack.
 */
public final class TpLimits {
  private TpLimits() {}

  /**
   * Deepest nesting of parentheses and prefix operators ({@code -}, {@code !}) in one
   * expression; far beyond what anyone types on a pendant.
   */
  public static final int MAX_NESTING = 64;

  /** Most operators in one statement; keeps trees shallow enough for recursive walkers. */
  public static final int MAX_OPERATORS = 1000;

  /** The nesting of parentheses and prefix operators in {@code e}; stops counting past {@code limit + 1}. */
  public static int nesting(Expr e, int limit) {
    return nesting(e, 0, limit);
  }

  private static int nesting(Expr e, int depth, int limit) {
    if (depth > limit) {
      return depth;
    }
    return switch (e) {
      case Expr.Group g -> nesting(g.inner(), depth + 1, limit);
      case Expr.Unary u -> nesting(u.operand(), depth + 1, limit);
      case Expr.Binary b -> {
        // Walk the left spine iteratively: a long chain a+b+c+... is wide, not nested.
        int worst = depth;
        Expr left = b;
        while (left instanceof Expr.Binary lb) {
          worst = Math.max(worst, nesting(lb.right(), depth, limit));
          left = lb.left();
        }
        yield Math.max(worst, nesting(left, depth, limit));
      }
      case Expr.MathFunc f -> nesting(f.arg(), depth + 1, limit);
      case Expr.StringFunc f -> {
        int worst = depth;
        for (Expr a : f.args()) {
          worst = Math.max(worst, nesting(a, depth, limit));
        }
        yield worst;
      }
      default -> depth;
    };
  }
}
