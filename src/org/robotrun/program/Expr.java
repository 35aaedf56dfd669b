package org.robotrun.program;

import java.util.List;
import java.util.Objects;

/**
 * An expression on the right of an assignment, in a condition, or as a CALL argument. The tree
 * is as written: {@link Group} keeps parentheses so a writer reproduces them, and FANUC's
 * unparenthesised short form {@code R[1]=R[2]+1} is the same tree without a Group.
 */
public sealed interface Expr {

  /** An integer constant ({@code 3}, {@code -7}); FANUC keeps integer and real apart. */
  record IntConst(int value) implements Expr {}

  /** A real constant ({@code 2.5}, {@code .20}). */
  record RealConst(double value) implements Expr {}

  /** {@code ON} / {@code OFF}. */
  record OnOff(boolean on) implements Expr {}

  /** A string constant, only meaningful as a CALL argument ({@code 'PART_A'}). */
  record StringConst(String value) implements Expr {
    public StringConst {
      Objects.requireNonNull(value, "value");
    }
  }

  /** A data register {@code R[i]} or {@code R[R[i]]}. */
  record Register(Item register) implements Expr {
    public Register {
      Objects.requireNonNull(register, "register");
    }
  }

  /**
   * One element of a position register, {@code PR[i,j]}: j = 1..6 is X, Y, Z, W, P, R (mm, deg)
   * of a Cartesian PR or J1..J6 (deg) of a joint PR. The comment in {@code PR[10,3:STACK]} is
   * the item's comment. The element j is a constant or {@code R[k]}
   * ({@code PR[1,R[4]]}), resolved when the line runs.
   */
  record PosElement(Item register, Index element) implements Expr {
    public PosElement {
      Objects.requireNonNull(register, "register");
      Objects.requireNonNull(element, "element");
    }

    public PosElement(Item register, int element) {
      this(register, Index.of(element));
    }
  }

  /** An I/O port or flag: {@code DI[i]}, {@code DO[i]}, {@code RI[i]}, {@code RO[i]}, {@code GI[i]}, {@code GO[i]}, {@code F[i]}. */
  record Io(IoKind kind, Item port) implements Expr {
    public Io {
      Objects.requireNonNull(kind, "kind");
      Objects.requireNonNull(port, "port");
    }
  }

  /** {@code TIMER[i]}: elapsed simulated seconds. */
  record Timer(Item timer) implements Expr {
    public Timer {
      Objects.requireNonNull(timer, "timer");
    }
  }

  /** {@code AR[i]}: the i-th argument of the current CALL. */
  /** A system variable RobotRun runs ({@link SystemVariables}), e.g. {@code $WAITTMOUT}. */
  record SysVar(String name) implements Expr {
    public SysVar {
      Objects.requireNonNull(name, "name");
    }
  }

  record Arg(Index index) implements Expr {
    public Arg {
      Objects.requireNonNull(index, "index");
    }
  }

  /** {@code SR[i]}: a string register. */
  record StringReg(Item register) implements Expr {
    public StringReg {
      Objects.requireNonNull(register, "register");
    }
  }

  /**
   * A string register function: {@code STRLEN SR[j]} (the length), {@code SUBSTR SR[j],m,n}
   * (n characters from the m-th), {@code FINDSTR SR[j],SR[k]} (where SR[k] starts in SR[j], 1-based,
   * 0 when it does not occur).
   */
  record StringFunc(StringFn fn, List<Expr> args) implements Expr {
    public StringFunc {
      Objects.requireNonNull(fn, "fn");
      args = List.copyOf(args);
      if (args.size() != fn.arity()) {
        throw new IllegalArgumentException(fn + " takes " + fn.arity() + " arguments, got " + args.size());
      }
    }
  }

  /**
   * {@code ABS[x]}, {@code SQRT[x]}, {@code SIN[x]} ...: an arithmetic function of the controller's
   * math-function option, its argument in square brackets (angles in degrees).
   */
  record MathFunc(MathFn fn, Expr arg) implements Expr {
    public MathFunc {
      Objects.requireNonNull(fn, "fn");
      Objects.requireNonNull(arg, "arg");
    }
  }

  /**
   * The one-argument arithmetic functions RobotRun runs. TRUNC and ROUND give integers; ABS keeps
   * its argument's type; the others give reals. (ATAN2 is read but not run: its argument order is
   * not confirmed.)
   */
  enum MathFn {
    ABS, SQRT, SIN, COS, TAN, ASIN, ACOS, ATAN, LN, EXP, TRUNC, ROUND
  }

  /** The string register functions of the controller. */
  enum StringFn {
    STRLEN(1), SUBSTR(3), FINDSTR(2);

    private final int arity;

    StringFn(int arity) {
      this.arity = arity;
    }

    /** How many arguments it takes. */
    public int arity() {
      return arity;
    }
  }

  /** {@code -x} or {@code !x} (NOT). */
  record Unary(UnaryOp op, Expr operand) implements Expr {
    public Unary {
      Objects.requireNonNull(op, "op");
      Objects.requireNonNull(operand, "operand");
    }
  }

  /** {@code left op right}. */
  record Binary(BinaryOp op, Expr left, Expr right) implements Expr {
    public Binary {
      Objects.requireNonNull(op, "op");
      Objects.requireNonNull(left, "left");
      Objects.requireNonNull(right, "right");
    }
  }

  /** A parenthesised subexpression {@code (inner)}, kept so the text can be reproduced. */
  record Group(Expr inner) implements Expr {
    public Group {
      Objects.requireNonNull(inner, "inner");
    }
  }

  /** Unary operators. */
  enum UnaryOp {
    /** Arithmetic negation {@code -x}. */
    MINUS("-"),
    /** Logical negation {@code !x}. */
    NOT("!");

    private final String symbol;

    UnaryOp(String symbol) {
      this.symbol = symbol;
    }

    /** The operator as FANUC writes it. */
    public String symbol() {
      return symbol;
    }
  }

  /**
   * Binary operators with their TP spelling and precedence inside parentheses (higher binds
   * tighter): {@code * / DIV MOD} 5, {@code + -} 4, comparisons 3, {@code AND} 2, {@code OR} 1.
   */
  enum BinaryOp {
    MUL("*", 5), DIVIDE("/", 5), DIV("DIV", 5), MOD("MOD", 5),
    ADD("+", 4), SUB("-", 4),
    EQ("=", 3), NE("<>", 3), LT("<", 3), LE("<=", 3), GT(">", 3), GE(">=", 3),
    AND("AND", 2),
    OR("OR", 1);

    private final String symbol;
    private final int precedence;

    BinaryOp(String symbol, int precedence) {
      this.symbol = symbol;
      this.precedence = precedence;
    }

    /** The operator as FANUC writes it ({@code DIV}, {@code <>}, {@code AND}). */
    public String symbol() {
      return symbol;
    }

    /** Binding strength inside parentheses; higher binds tighter. All are left-associative. */
    public int precedence() {
      return precedence;
    }
  }
}
