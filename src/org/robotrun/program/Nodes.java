package org.robotrun.program;

/**
 * Compiled expressions: a tree of small objects whose {@code eval} returns the value as a double
 * and leaves its type in {@link Interpreter#kind} (and a string in {@link Interpreter#str}), so
 * evaluation allocates nothing. Built by {@link Compiler} from {@link Expr}.
 */
final class Nodes {
  private Nodes() {}

  // Value types of an evaluated expression.
  static final int INT = 0;
  static final int REAL = 1;
  static final int BOOL = 2;
  static final int STR = 3;

  static String typeName(int kind) {
    return switch (kind) {
      case INT -> "an integer";
      case REAL -> "a real";
      case BOOL -> "ON/OFF";
      default -> "a string";
    };
  }

  static AlarmSignal mismatch(String what, int kind) {
    return new AlarmSignal(AlarmKind.TYPE_MISMATCH, what + ", got " + typeName(kind));
  }

  static AlarmSignal badIndex(String table, int index, int size) {
    return new AlarmSignal(AlarmKind.BAD_INDEX, table + "[" + index + "]: index out of range (expected 1.." + size + ")");
  }

  static int check(String table, int index, int size) {
    if (index < 1 || index > size) {
      throw badIndex(table, index, size);
    }
    return index;
  }

  /** A whole number that fits an int, or -1 marker handled by callers via the flag. */
  static boolean isWhole(double v) {
    return v == Math.rint(v) && v >= Integer.MIN_VALUE && v <= Integer.MAX_VALUE;
  }

  /** An index {@code [n]} or {@code [R[i]]}, resolved at run time. */
  static final class Idx {
    final int direct;
    /** 0 when direct; otherwise the R[] number holding the index. */
    final int viaRegister;
    /** 0 unless the index is the CALL argument AR[viaArg]. */
    final int viaArg;

    Idx(Index index) {
      switch (index) {
        case Index.Direct d -> {
          direct = d.value();
          viaRegister = 0;
          viaArg = 0;
        }
        case Index.Indirect i -> {
          direct = 0;
          viaRegister = i.register();
          viaArg = 0;
        }
        case Index.ViaArg a -> {
          direct = 0;
          viaRegister = 0;
          viaArg = a.arg();
        }
      }
    }

    int resolve(Interpreter m) {
      if (viaArg != 0) {
        return m.argAsIndex(viaArg);
      }
      return viaRegister == 0 ? direct : m.registerAsIndex(viaRegister);
    }
  }

  abstract static class Node {
    /** The value; its type is left in {@code m.kind}. */
    abstract double eval(Interpreter m);

    /** Evaluates and requires a number (integer or real). */
    final double number(Interpreter m, String what) {
      double v = eval(m);
      if (m.kind > REAL) {
        throw mismatch(what + " needs a number", m.kind);
      }
      return v;
    }

    /** Evaluates and requires ON/OFF. */
    final boolean bool(Interpreter m, String what) {
      double v = eval(m);
      if (m.kind != BOOL) {
        throw mismatch(what + " needs ON/OFF or a condition", m.kind);
      }
      return v != 0;
    }

    /** Evaluates and requires a whole number (FOR bounds, GO values, indices). */
    final int integer(Interpreter m, String what) {
      double v = eval(m);
      if (m.kind > REAL || !isWhole(v)) {
        throw m.kind > REAL ? mismatch(what + " needs an integer", m.kind)
            : new AlarmSignal(AlarmKind.TYPE_MISMATCH, what + " needs an integer, got " + v);
      }
      return (int) v;
    }
  }

  static final class Const extends Node {
    final double value;
    final int type;

    Const(double value, int type) {
      this.value = value;
      this.type = type;
    }

    @Override
    double eval(Interpreter m) {
      m.kind = type;
      return value;
    }
  }

  static final class StrConst extends Node {
    final String value;

    StrConst(String value) {
      this.value = value;
    }

    @Override
    double eval(Interpreter m) {
      m.kind = STR;
      m.str = value;
      return 0;
    }
  }

  /** {@code R[n]} with n checked at compile time. */
  static final class RegDirect extends Node {
    final int i;

    RegDirect(int i) {
      this.i = i;
    }

    @Override
    double eval(Interpreter m) {
      Registers g = m.regs;
      m.kind = g.rIsInteger[i] ? INT : REAL;
      return g.r[i];
    }
  }

  /** {@code R[R[j]]} (or a direct index out of range, which alarms when read). */
  static final class RegIndexed extends Node {
    final Idx idx;

    RegIndexed(Idx idx) {
      this.idx = idx;
    }

    @Override
    double eval(Interpreter m) {
      int i = check("R", idx.resolve(m), Registers.R_COUNT);
      Registers g = m.regs;
      m.kind = g.rIsInteger[i] ? INT : REAL;
      return g.r[i];
    }
  }

  static final class PosElement extends Node {
    final Idx idx;
    final Idx elementIdx;

    PosElement(Idx idx, Idx element) {
      this.idx = idx;
      this.elementIdx = element;
    }

    @Override
    double eval(Interpreter m) {
      int i = check("PR", idx.resolve(m), Registers.PR_COUNT);
      int element = elementIdx.resolve(m);
      if (element < 1 || element > Position.ELEMENTS) {
        throw new AlarmSignal(AlarmKind.BAD_INDEX, "PR[" + i + "," + element + "]: element out of range (expected 1..6)");
      }
      m.kind = REAL;
      return m.regs.pr[i].element(element);
    }
  }

  static final class IoRead extends Node {
    final IoKind io;
    final Idx idx;

    IoRead(IoKind io, Idx idx) {
      this.io = io;
      this.idx = idx;
    }

    @Override
    double eval(Interpreter m) {
      int i = check(io.name(), idx.resolve(m), m.regs.ioSize(io));
      int v = m.regs.io[io.ordinal()][i];
      if (io.group()) {
        m.kind = INT;
        return v;
      }
      m.kind = BOOL;
      return v != 0 ? 1 : 0;
    }
  }

  /** A system variable's value (SystemVariables): $WAITTMOUT in 1/100 s, $MCR.$GENOVERRIDE in percent, frame numbers (integers). */
  static final class SysVarRead extends Node {
    final String name;

    SysVarRead(String name) {
      this.name = name;
    }

    @Override
    double eval(Interpreter m) {
      m.kind = INT;
      return switch (name) {
        case SystemVariables.WAITTMOUT -> Math.round(m.waitTimeoutSec * 100);
        case SystemVariables.GENOVERRIDE -> m.port.overridePct();
        case SystemVariables.TOOLNUM -> m.port.activeFrame(Instruction.FrameKind.TOOL);
        case SystemVariables.FRAMENUM -> m.port.activeFrame(Instruction.FrameKind.USER);
        case SystemVariables.JOG_GROUP -> 1;
        default -> {
          int slot = SystemVariables.backgroundSlot(name);
          if (slot == 0) {
            throw new IllegalStateException("no system variable " + name);
          }
          yield m.taskPort().backgroundStatus(slot);
        }
      };
    }
  }

  static final class TimerRead extends Node {
    final Idx idx;

    TimerRead(Idx idx) {
      this.idx = idx;
    }

    @Override
    double eval(Interpreter m) {
      int i = check("TIMER", idx.resolve(m), Registers.TIMER_COUNT);
      m.kind = REAL;
      return m.regs.timerSec(i);
    }
  }

  static final class ArgRead extends Node {
    final Idx idx;

    ArgRead(Idx idx) {
      this.idx = idx;
    }

    @Override
    double eval(Interpreter m) {
      return m.readArg(idx.resolve(m));
    }
  }

  /** {@code SR[i]}. */
  static final class SrRead extends Node {
    final Idx idx;

    SrRead(Idx idx) {
      this.idx = idx;
    }

    @Override
    double eval(Interpreter m) {
      int i = check("SR", idx.resolve(m), Registers.SR_COUNT);
      m.kind = STR;
      m.str = m.regs.string(i);
      return 0;
    }
  }

  /** The text of the value just evaluated: a string as it is, a number as the controller prints it. */
  static String text(Interpreter m, double v, String what) {
    return switch (m.kind) {
      case STR -> m.str;
      case INT -> Long.toString((long) v);
      case REAL -> realText(v);
      default -> throw mismatch(what + " needs a string or a number", m.kind);
    };
  }

  /**
   * A real as text: up to six decimals, trailing zeros dropped but one decimal kept ({@code 2.5},
   * {@code 3.0}). RobotRun's choice: we could not check the controller's exact conversion format.
   */
  static String realText(double v) {
    java.math.BigDecimal b = java.math.BigDecimal.valueOf(v).setScale(6, java.math.RoundingMode.HALF_UP).stripTrailingZeros();
    String t = b.toPlainString();
    return t.indexOf('.') < 0 ? t + ".0" : t;
  }

  /**
   * A string as a number (R[i]=SR[j]): its leading number ({@code "12AB"} gives 12, {@code "2.5"}
   * gives the real 2.5); a string with no leading number alarms (type mismatch).
   */
  static double number(Interpreter m, String s, String what) {
    String t = s.strip();
    int k = 0;
    if (k < t.length() && (t.charAt(k) == '-' || t.charAt(k) == '+')) {
      k++;
    }
    int digits = k;
    while (k < t.length() && Character.isDigit(t.charAt(k))) {
      k++;
    }
    boolean real = false;
    if (k < t.length() && t.charAt(k) == '.') {
      real = true;
      k++;
      while (k < t.length() && Character.isDigit(t.charAt(k))) {
        k++;
      }
    }
    String num = t.substring(0, k);
    if (k == digits || num.equals(".") || num.endsWith("-.") || num.endsWith("+.")) {
      throw new AlarmSignal(AlarmKind.TYPE_MISMATCH, what + ": '" + clip(s) + "' does not start with a number");
    }
    double v = Double.parseDouble(num);
    if (!real && isWhole(v)) {
      m.kind = INT;
    } else {
      m.kind = REAL;
    }
    return finite(v);
  }

  private static String clip(String s) {
    return s.length() <= 20 ? s : s.substring(0, 20) + "...";
  }

  /** ABS[], SQRT[], SIN[] ...: the controller's arithmetic functions, angles in degrees. */
  static final class MathFunc extends Node {
    final Expr.MathFn fn;
    final Node arg;

    MathFunc(Expr.MathFn fn, Node arg) {
      this.fn = fn;
      this.arg = arg;
    }

    @Override
    double eval(Interpreter m) {
      double v = arg.eval(m);
      if (m.kind > REAL) {
        throw mismatch(fn.name() + "[] needs a number", m.kind);
      }
      int argKind = m.kind;
      m.kind = REAL;
      double r = switch (fn) {
        case ABS -> {
          m.kind = argKind;
          yield Math.abs(v);
        }
        case SQRT -> {
          if (v < 0) {
            throw new AlarmSignal(AlarmKind.BAD_VALUE, "SQRT[" + v + "]: the argument is negative");
          }
          yield Math.sqrt(v);
        }
        case SIN -> Math.sin(Math.toRadians(v));
        case COS -> Math.cos(Math.toRadians(v));
        case TAN -> Math.tan(Math.toRadians(v));
        case ASIN, ACOS -> {
          if (v < -1 || v > 1) {
            throw new AlarmSignal(AlarmKind.BAD_VALUE, fn.name() + "[" + v + "]: the argument is outside -1..1");
          }
          yield Math.toDegrees(fn == Expr.MathFn.ASIN ? Math.asin(v) : Math.acos(v));
        }
        case ATAN -> Math.toDegrees(Math.atan(v));
        case LN -> {
          if (!(v > 0)) {
            throw new AlarmSignal(AlarmKind.BAD_VALUE, "LN[" + v + "]: the argument must be greater than 0");
          }
          yield Math.log(v);
        }
        case EXP -> Math.exp(v);
        case TRUNC, ROUND -> {
          double w = fn == Expr.MathFn.TRUNC ? (v < 0 ? Math.ceil(v) : Math.floor(v))
              : Math.signum(v) * Math.floor(Math.abs(v) + 0.5);
          if (Math.abs(w) > Integer.MAX_VALUE) {
            throw new AlarmSignal(AlarmKind.BAD_VALUE, fn.name() + "[" + v + "]: the result is not an integer register value");
          }
          m.kind = INT;
          yield w + 0.0;
        }
      };
      if (!Double.isFinite(r)) {
        throw new AlarmSignal(AlarmKind.BAD_VALUE, fn.name() + "[" + v + "]: the result is not a finite number");
      }
      return r;
    }
  }

  /** STRLEN, SUBSTR, FINDSTR. */
  static final class StrFunc extends Node {
    final Expr.StringFn fn;
    final Node[] args;

    StrFunc(Expr.StringFn fn, Node[] args) {
      this.fn = fn;
      this.args = args;
    }

    @Override
    double eval(Interpreter m) {
      String s = text(m, args[0].eval(m), fn.name());
      switch (fn) {
        case STRLEN -> {
          m.kind = INT;
          return s.length();
        }
        case FINDSTR -> {
          String what = text(m, args[1].eval(m), "FINDSTR");
          // case-insensitive, 1-based, 0 when not found (HandlingTool manual, string registers, as cited)
          int at = s.toUpperCase(java.util.Locale.ROOT).indexOf(what.toUpperCase(java.util.Locale.ROOT));
          m.kind = INT;
          return at + 1;
        }
        case SUBSTR -> {
          int start = args[1].integer(m, "SUBSTR start");
          int len = args[2].integer(m, "SUBSTR length");
          if (start < 1 || len < 1 || start - 1 + len > s.length()) {
            throw new AlarmSignal(AlarmKind.BAD_VALUE, "SUBSTR from " + start + ", " + len + " characters: the string has "
                + s.length() + " characters");
          }
          m.kind = STR;
          m.str = s.substring(start - 1, start - 1 + len);
          return 0;
        }
        default -> throw new IllegalStateException(fn.name());
      }
    }
  }

  static final class Neg extends Node {
    final Node a;

    Neg(Node a) {
      this.a = a;
    }

    @Override
    double eval(Interpreter m) {
      double v = a.eval(m);
      if (m.kind > REAL) {
        throw mismatch("unary '-' needs a number", m.kind);
      }
      return -v;
    }
  }

  static final class Not extends Node {
    final Node a;

    Not(Node a) {
      this.a = a;
    }

    @Override
    double eval(Interpreter m) {
      double v = a.eval(m);
      if (m.kind != BOOL) {
        throw mismatch("'!' needs ON/OFF or a condition", m.kind);
      }
      return v != 0 ? 0 : 1;
    }
  }

  /** Integer result when both operands are integers and it fits 32 bits (as FANUC's R[]); else real. */
  static int numericKind(int ka, int kb, double result) {
    finite(result);
    return ka == INT && kb == INT && result >= Integer.MIN_VALUE && result <= Integer.MAX_VALUE ? INT : REAL;
  }

  /**
   * {@code v}, or an alarm when arithmetic overflowed: a controller stops the program on a
   * result its registers cannot hold instead of storing a wrong value. (The code is the
   * interpreter table's "Invalid value"; see AlarmKind.)
   */
  static double finite(double v) {
    if (!Double.isFinite(v)) {
      throw new AlarmSignal(AlarmKind.BAD_VALUE, "value overflow: the result is beyond the range of a register");
    }
    return v;
  }

  static final class Add extends Node {
    final Node a;
    final Node b;

    Add(Node a, Node b) {
      this.a = a;
      this.b = b;
    }

    @Override
    double eval(Interpreter m) {
      double x = a.eval(m);
      int ka = m.kind;
      String sa = m.str;
      double y = b.eval(m);
      int kb = m.kind;
      if (ka == STR || kb == STR) {
        // SR[1]=SR[2]+R[3]: a string joined with a string or a number's text
        String right = text(m, y, "'+'");
        m.kind = ka;
        m.str = sa;
        String left = text(m, x, "'+'");
        m.kind = STR;
        m.str = left + right;
        return 0;
      }
      if ((ka | kb) > REAL) {
        throw mismatch("'+' needs numbers", Math.max(ka, kb));
      }
      double r = x + y;
      m.kind = numericKind(ka, kb, r);
      return r;
    }
  }

  static final class Sub extends Node {
    final Node a;
    final Node b;

    Sub(Node a, Node b) {
      this.a = a;
      this.b = b;
    }

    @Override
    double eval(Interpreter m) {
      double x = a.eval(m);
      int ka = m.kind;
      double y = b.eval(m);
      int kb = m.kind;
      if ((ka | kb) > REAL) {
        throw mismatch("'-' needs numbers", Math.max(ka, kb));
      }
      double r = x - y;
      m.kind = numericKind(ka, kb, r);
      return r;
    }
  }

  static final class Mul extends Node {
    final Node a;
    final Node b;

    Mul(Node a, Node b) {
      this.a = a;
      this.b = b;
    }

    @Override
    double eval(Interpreter m) {
      double x = a.eval(m);
      int ka = m.kind;
      double y = b.eval(m);
      int kb = m.kind;
      if ((ka | kb) > REAL) {
        throw mismatch("'*' needs numbers", Math.max(ka, kb));
      }
      double r = x * y;
      m.kind = numericKind(ka, kb, r);
      return r;
    }
  }

  /** {@code /}: always a real result; {@code DIV}: quotient truncated toward zero; {@code MOD}: sign of the dividend. */
  static final class Division extends Node {
    final Expr.BinaryOp op;
    final Node a;
    final Node b;

    Division(Expr.BinaryOp op, Node a, Node b) {
      this.op = op;
      this.a = a;
      this.b = b;
    }

    @Override
    double eval(Interpreter m) {
      double x = a.eval(m);
      int ka = m.kind;
      double y = b.eval(m);
      int kb = m.kind;
      if ((ka | kb) > REAL) {
        throw mismatch("'" + op.symbol() + "' needs numbers", Math.max(ka, kb));
      }
      if (y == 0) {
        throw new AlarmSignal(AlarmKind.DIVIDE_BY_ZERO, "division by zero in '" + op.symbol() + "'");
      }
      return switch (op) {
        case DIVIDE -> {
          m.kind = REAL;
          yield finite(x / y);
        }
        case DIV -> {
          // FANUC DIV: the integer part of the quotient, truncated toward zero (-7 DIV 2 = -3).
          double q = x / y;
          double r = q < 0 ? Math.ceil(q) : Math.floor(q);
          m.kind = numericKind(INT, INT, r);
          yield r;
        }
        case MOD -> {
          // FANUC MOD: remainder with the sign of the dividend (-7 MOD 2 = -1), i.e. x - (x DIV y) * y;
          // Java's % on doubles is exactly that (IEEE fmod).
          double r = x % y;
          m.kind = numericKind(ka, kb, r);
          yield r;
        }
        case ADD, SUB, MUL, EQ, NE, LT, LE, GT, GE, AND, OR -> throw new IllegalStateException(op + " is not a division");
      };
    }
  }

  static final class Compare extends Node {
    final Expr.BinaryOp op;
    final Node a;
    final Node b;

    Compare(Expr.BinaryOp op, Node a, Node b) {
      this.op = op;
      this.a = a;
      this.b = b;
    }

    @Override
    double eval(Interpreter m) {
      double x = a.eval(m);
      int ka = m.kind;
      String sx = m.str;
      double y = b.eval(m);
      int kb = m.kind;
      boolean numbers = ka <= REAL && kb <= REAL;
      boolean r;
      if (numbers) {
        r = switch (op) {
          case EQ -> x == y;
          case NE -> x != y;
          case LT -> x < y;
          case LE -> x <= y;
          case GT -> x > y;
          case GE -> x >= y;
          case ADD, SUB, MUL, DIVIDE, DIV, MOD, AND, OR -> throw new IllegalStateException(op + " is not a comparison");
        };
      } else if (ka == kb && (op == Expr.BinaryOp.EQ || op == Expr.BinaryOp.NE)) {
        boolean same = ka == STR ? sx.equals(m.str) : x == y;
        r = (op == Expr.BinaryOp.EQ) == same;
      } else {
        throw new AlarmSignal(AlarmKind.TYPE_MISMATCH,
            "'" + op.symbol() + "' cannot compare " + typeName(ka) + " with " + typeName(kb));
      }
      m.kind = BOOL;
      return r ? 1 : 0;
    }
  }

  /** AND / OR: both operands are evaluated (no short circuit), as on the controller. */
  static final class Logic extends Node {
    final boolean and;
    final Node a;
    final Node b;

    Logic(boolean and, Node a, Node b) {
      this.and = and;
      this.a = a;
      this.b = b;
    }

    @Override
    double eval(Interpreter m) {
      boolean x = a.bool(m, and ? "AND" : "OR");
      boolean y = b.bool(m, and ? "AND" : "OR");
      m.kind = BOOL;
      return (and ? x && y : x || y) ? 1 : 0;
    }
  }
}
