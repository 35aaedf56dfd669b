package org.robotrun.sim;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.robotrun.control.RobotControl;
import org.robotrun.program.IoKind;
import org.robotrun.program.Registers;
import org.robotrun.world.ProductionSetup;
import org.robotrun.world.ProductionSetup.PlcStep;
import org.robotrun.world.ProductionSetup.ReferencePosition;
import org.robotrun.world.ProductionSetup.Selection;

/**
 * The UOP (user operator panel) signals of one controller, as an R-30iB gives them meaning, read
 * and written once per tick before the programs run. UI[] are set by the PLC (the PLC panel, a
 * scenario's PLC sequence, a key script); UO[] are set here and only read by programs.
 *
 * <pre>
 * UI[1] *IMSTP   UI[2] *HOLD   UI[3] *SFSPD   UI[4] CSTOPI   UI[5] FAULT RESET   UI[6] START
 * UI[7] HOME     UI[8] ENBL    UI[9..16] RSR1..8 / PNS1..8 / STYLE1..8   UI[17] PNSTROBE   UI[18] PROD_START
 * UO[1] CMDENBL  UO[2] SYSRDY  UO[3] PROGRUN  UO[4] PAUSED  UO[5] HELD  UO[6] FAULT  UO[7] ATPERCH
 * UO[8] TPENBL   UO[9] BATALM  UO[10] BUSY    UO[11..18] ACK1..8 / SNO1..8   UO[19] SNACK   UO[20] reserved
 * </pre>
 *
 * <p>*IMSTP, *HOLD and *SFSPD are active-low (the PLC keeps them ON; OFF stops). START and PROD_START
 * act on their falling edge (ON then OFF), PNSTROBE, RSR, CSTOPI, FAULT RESET and HOME on their
 * rising edge. Programs are started from the PLC only while CMDENBL is ON: UOP enabled, Remote,
 * mode AUTO, pendant disabled, not in step mode, *IMSTP, *HOLD, *SFSPD and ENBL ON.
 * docs/production.md says what is simplified.
 */
public final class Uop {
  public static final int IMSTP = 1;
  public static final int HOLD = 2;
  public static final int SFSPD = 3;
  public static final int CSTOPI = 4;
  public static final int FAULT_RESET = 5;
  public static final int START = 6;
  public static final int HOME = 7;
  public static final int ENBL = 8;
  public static final int SEL1 = 9;
  public static final int PNSTROBE = 17;
  public static final int PROD_START = 18;

  public static final int CMDENBL = 1;
  public static final int SYSRDY = 2;
  public static final int PROGRUN = 3;
  public static final int PAUSED = 4;
  public static final int HELD = 5;
  public static final int FAULT = 6;
  public static final int ATPERCH = 7;
  public static final int TPENBL = 8;
  public static final int BATALM = 9;
  public static final int BUSY = 10;
  public static final int ACK1 = 11;
  public static final int SNACK = 19;

  /** The names of UI[1..18], as the I/O UOP screen shows them (index 0 unused). */
  public static final List<String> UI_NAMES = List.of("", "*IMSTP", "*HOLD", "*SFSPD", "CSTOPI", "FAULT RESET", "START",
      "HOME", "ENBL", "RSR1/PNS1", "RSR2/PNS2", "RSR3/PNS3", "RSR4/PNS4", "RSR5/PNS5", "RSR6/PNS6", "RSR7/PNS7",
      "RSR8/PNS8", "PNSTROBE", "PROD_START");

  /** The names of UO[1..20] (index 0 unused). */
  public static final List<String> UO_NAMES = List.of("", "CMDENBL", "SYSRDY", "PROGRUN", "PAUSED", "HELD", "FAULT",
      "ATPERCH", "TPENBL", "BATALM", "BUSY", "ACK1/SNO1", "ACK2/SNO2", "ACK3/SNO3", "ACK4/SNO4", "ACK5/SNO5",
      "ACK6/SNO6", "ACK7/SNO7", "ACK8/SNO8", "SNACK", "RESERVED");

  /** Override the controller limits the arm to while *SFSPD is off ($SCR.$FENCEOVRD). */
  public static final int FENCE_OVERRIDE_PCT = 10;

  private final Controller c;
  private ProductionSetup.Robot setup = null;
  private final boolean[] lastUi = new boolean[19];
  private boolean tpEnabled;
  private int pnsSelected;
  private String selected = "";
  private double snackLeftSec;
  private final double[] ackLeftSec = new double[8];
  private final Deque<String> rsrQueue = new ArrayDeque<>();
  /** *SFSPD is off (the safety fence is open): the override is held at or below the fence limit. */
  private boolean fenceOpen;
  private double simSec;
  /** PLC sequence: current step, seconds since its condition held (NaN: not yet). */
  private int plcStep;
  private double plcHeldSec = Double.NaN;
  private String lastRefusal = "";
  /**
   * The setup resolved once when it is applied, so a tick looks nothing up by name: each
   * reference position's joints and tolerances (deg) and output kind, each PLC step's awaited
   * input kind and its outputs.
   */
  private double[][] refJointsDeg = new double[0][];
  private double[][] refToleranceDeg = new double[0][];
  private IoKind[] refOutputKind = new IoKind[0];
  private IoKind[] plcWaitKind = new IoKind[0];
  private List<List<SetBit>> plcSets = List.of();

  /** One output a PLC step sets, its kind resolved. */
  private record SetBit(IoKind kind, int index, boolean on) {}

  Uop(Controller c) {
    this.c = c;
  }

  /** Applies a robot's production setup; null (or none) disables the UOP inputs, as "Enable UI signals: FALSE". */
  public void configure(ProductionSetup.Robot robot) {
    this.setup = robot;
    resolve(robot);
    plcStep = 0;
    plcHeldSec = Double.NaN;
    rsrQueue.clear();
    if (robot != null && robot.plc().isEmpty()) {
      // nothing drives the inputs: hold the active-low ones and ENBL on, as a PLC that is just switched on would
      setUi(IMSTP, true);
      setUi(HOLD, true);
      setUi(SFSPD, true);
      setUi(ENBL, true);
    }
    for (int i = 1; i <= 18; i++) {
      lastUi[i] = ui(i);
    }
  }

  private void resolve(ProductionSetup.Robot robot) {
    List<ReferencePosition> refs = robot == null ? List.of() : robot.referencePositions();
    refJointsDeg = new double[refs.size()][];
    refToleranceDeg = new double[refs.size()][];
    refOutputKind = new IoKind[refs.size()];
    for (int k = 0; k < refs.size(); k++) {
      ReferencePosition r = refs.get(k);
      refJointsDeg[k] = r.jointsDeg().stream().mapToDouble(Double::doubleValue).toArray();
      refToleranceDeg[k] = r.toleranceDeg().stream().mapToDouble(Double::doubleValue).toArray();
      refOutputKind[k] = r.output().map(o -> IoKind.valueOf(o.kind())).orElse(null);
    }
    List<PlcStep> steps = robot == null ? List.of() : robot.plc();
    plcWaitKind = new IoKind[steps.size()];
    List<List<SetBit>> sets = new ArrayList<>();
    for (int k = 0; k < steps.size(); k++) {
      PlcStep st = steps.get(k);
      plcWaitKind[k] = st.waitFor().map(w -> IoKind.valueOf(w.getKey().kind())).orElse(null);
      List<SetBit> bits = new ArrayList<>();
      st.set().forEach((sig, on) -> bits.add(new SetBit(IoKind.valueOf(sig.kind()), sig.index(), on)));
      sets.add(List.copyOf(bits));
    }
    plcSets = List.copyOf(sets);
  }

  /**
   * Restarts the PLC sequence from its first step with every UI input OFF, as a PLC that is
   * switched off and on again (the PLC panel's button).
   */
  public void restartPlc() {
    for (int i = 1; i <= 18; i++) {
      setUi(i, false);
    }
    plcStep = 0;
    plcHeldSec = Double.NaN;
    rsrQueue.clear();
  }

  /** The setup now, if any. */
  public Optional<ProductionSetup.Robot> setup() {
    return Optional.ofNullable(setup);
  }

  /** Whether the UOP inputs are obeyed (a production setup with "Enable UI signals" on). */
  public boolean enabled() {
    return setup != null && setup.uopEnabled();
  }

  /** Whether the teach pendant's TP ENABLE switch is on (UO TPENBL). */
  public boolean tpEnabled() {
    return tpEnabled;
  }

  /** The teach pendant's TP ENABLE switch (the window tells the controller; headless it is off). */
  public void setTpEnabled(boolean on) {
    tpEnabled = on;
  }

  /** The program PNS/Style/RSR selected last, "" when none. */
  public String selectedProgram() {
    return selected;
  }

  /** The PNS/Style number read at the last PNSTROBE. */
  public int selectedNumber() {
    return pnsSelected;
  }

  /** Why the last PLC start was refused, "" when none. */
  public String lastRefusal() {
    return lastRefusal;
  }

  /** The step the PLC sequence is on (0-based; = size when it is done). */
  public int plcStep() {
    return plcStep;
  }

  /** Whether the PLC sequence ran to its end (true when there is none). */
  public boolean plcDone() {
    return setup == null || plcStep >= setup.plc().size();
  }

  public boolean ui(int i) {
    return c.registers().bit(IoKind.UI, i);
  }

  public void setUi(int i, boolean on) {
    c.registers().setBit(IoKind.UI, i, on);
  }

  public boolean uo(int i) {
    return c.registers().bit(IoKind.UO, i);
  }

  private void setUo(int i, boolean on) {
    c.registers().setBit(IoKind.UO, i, on);
  }

  /** The remote conditions and the operation enable conditions hold (CMDENBL's inputs, less step mode). */
  private boolean remoteOk() {
    return enabled() && setup.remote() && c.mode() == RobotControl.Mode.AUTO && !tpEnabled
        && ui(IMSTP) && ui(HOLD) && ui(SFSPD) && ui(ENBL);
  }

  /** UO[1] CMDENBL: a program may be started from the PLC. */
  public boolean cmdEnabled() {
    return remoteOk() && !c.stepMode();
  }

  /** One tick, before the programs run: the PLC sequence, the inputs' edges, then the outputs. */
  void tick(double dtSec) {
    simSec += dtSec;
    if (setup != null) {
      stepPlc(dtSec);
    }
    if (enabled()) {
      readInputs();
    }
    for (int i = 1; i <= 18; i++) {
      lastUi[i] = ui(i);
    }
    writeOutputs(dtSec);
  }

  /**
   * Writes the UOP outputs once more from the controller's state now, with no time passing: the
   * outputs otherwise follow at the next tick, and a run that ends on this tick has no next one
   * (PROGRUN and BUSY of the last robot to finish would stay ON in the report).
   */
  void settleOutputs() {
    writeOutputs(0);
  }

  private boolean imstpAlarmActive() {
    String code = org.robotrun.program.AlarmCode.SRVO_037.code();
    return c.activeAlarms().stream().anyMatch(a -> a.code().equals(code));
  }

  private boolean rose(int i) {
    return ui(i) && !lastUi[i];
  }

  private boolean fell(int i) {
    return !ui(i) && lastUi[i];
  }

  private void readInputs() {
    if (rose(FAULT_RESET)) {
      c.reset();
    }
    // *IMSTP off: an immediate stop (servo off) as long as it stays off; a RESET while it is still
    // off does not end it (the alarm is raised again at once)
    if (!ui(IMSTP)) {
      if (!imstpAlarmActive()) {
        c.raiseServoAlarm(org.robotrun.program.AlarmCode.SRVO_037);
      }
    }
    if (!ui(HOLD) || !ui(ENBL)) {
      c.hold();
    }
    if (!ui(SFSPD)) {
      if (!fenceOpen) {
        fenceOpen = true;
        c.hold();
      }
      // while the fence is open the override stays at most the fence limit (raising it is clamped back)
      if (c.overridePct() > FENCE_OVERRIDE_PCT) {
        c.setOverridePct(FENCE_OVERRIDE_PCT);
      }
    } else {
      fenceOpen = false;
    }
    if (rose(CSTOPI)) {
      rsrQueue.clear();
      if (setup.cstopiAborts()) {
        c.abort();
      }
    }
    boolean ok = cmdEnabled();
    if (rose(HOME) && ok && setup.homeProgram().isPresent()) {
      String home = setup.homeProgram().get();
      Optional<String> r = c.tasks().run(home);
      r.ifPresent(why -> refuse("HOME: " + why));
    }
    switch (setup.selection()) {
      case RSR -> readRsr(ok);
      case PNS -> readPns(ok);
      case STYLE -> readStyle(ok);
      case OTHER -> {
        if (fell(PROD_START) && ok) {
          startSelected(c.status().program());
        }
      }
    }
    if (fell(START) && ok) {
      ExecutionStatus s = c.status();
      if (s.state() == ExecutionStatus.State.PAUSED) {
        c.run(s.program(), s.line(), true);
      } else if (!setup.startForContinueOnly() && s.state() == ExecutionStatus.State.IDLE && !s.program().isEmpty()) {
        c.run(s.program(), s.line(), true);
      }
    }
    if (!rsrQueue.isEmpty() && ok && c.status().state() == ExecutionStatus.State.IDLE && !c.busy()) {
      startSelected(rsrQueue.poll());
    }
  }

  private int selectionNumber() {
    int n = 0;
    for (int b = 0; b < 8; b++) {
      if (ui(SEL1 + b)) {
        n |= 1 << b;
      }
    }
    return n;
  }

  private void readPns(boolean ok) {
    if (rose(PNSTROBE) && ok) {
      pnsSelected = selectionNumber();
      selected = pnsSelected == 0 ? "" : String.format(Locale.ROOT, "PNS%04d", setup.pnsBase() + pnsSelected);
      snackLeftSec = setup.ackPulseSec();
    }
    if (fell(PROD_START) && ok) {
      if (selected.isEmpty()) {
        refuse("PNS number 0: no program selected (set PNS1..8, then PNSTROBE)");
      } else {
        startSelected(selected);
      }
    }
  }

  private void readStyle(boolean ok) {
    if (fell(PROD_START) && ok) {
      pnsSelected = selectionNumber();
      String p = setup.styles().get(pnsSelected);
      if (p == null) {
        refuse("style " + pnsSelected + " has no program in the style table");
        return;
      }
      selected = p;
      snackLeftSec = setup.ackPulseSec();
      startSelected(p);
    }
  }

  private void readRsr(boolean ok) {
    for (int i = 0; i < 8; i++) {
      if (!rose(SEL1 + i) || !ok) {
        continue;
      }
      int number = setup.rsrNumbers().get(i);
      if (number == 0) {
        continue; // that RSR is disabled: the controller ignores it
      }
      String p = String.format(Locale.ROOT, "RSR%04d", setup.rsrBase() + number);
      ackLeftSec[i] = setup.ackPulseSec();
      selected = p;
      if (c.status().state() == ExecutionStatus.State.IDLE && !c.busy() && rsrQueue.isEmpty()) {
        startSelected(p);
      } else {
        rsrQueue.add(p); // the controller queues RSR requests that come while a program runs
      }
    }
  }

  private void startSelected(String program) {
    if (program == null || program.isEmpty()) {
      refuse("no program selected");
      return;
    }
    if (c.program(program).isEmpty()) {
      refuse("program " + program + " does not exist");
      return;
    }
    if (c.tasks().isRunning(program)) {
      refuse(program + " is already running");
      return;
    }
    RobotControl.Result r = c.run(program, 1, true);
    if (r instanceof RobotControl.Result.Refused f) {
      refuse(f.reason());
    }
  }

  private void refuse(String why) {
    lastRefusal = why;
    c.raiseRunFailed(why);
  }

  private void writeOutputs(double dtSec) {
    ExecutionStatus s = c.status();
    boolean running = s.state() == ExecutionStatus.State.RUNNING || c.tasks().anyRunning();
    setUo(CMDENBL, cmdEnabled());
    setUo(SYSRDY, !c.estopped() && !c.servoOff());
    setUo(PROGRUN, running);
    setUo(PAUSED, !running && (s.state() == ExecutionStatus.State.PAUSED || c.tasks().anyPaused()));
    setUo(HELD, enabled() && !ui(HOLD));
    setUo(FAULT, c.hasActiveAlarm());
    setUo(TPENBL, tpEnabled);
    setUo(BATALM, false);
    setUo(BUSY, running || c.busy());
    // reference positions: ATPERCH follows reference position 1 (the joints read once a tick)
    boolean atPerch = false;
    if (setup != null && !setup.referencePositions().isEmpty()) {
      org.robotrun.program.Position.Joint q = c.currentJoints();
      List<ReferencePosition> refs = setup.referencePositions();
      for (int k = 0; k < refs.size(); k++) {
        ReferencePosition r = refs.get(k);
        boolean in = within(q, refJointsDeg[k], refToleranceDeg[k]);
        if (r.number() == 1) {
          atPerch = in;
        }
        if (refOutputKind[k] != null) {
          c.registers().setBit(refOutputKind[k], r.output().get().index(), in);
        }
      }
    }
    setUo(ATPERCH, atPerch);
    // ACK1..8 (RSR) or SNO1..8 (PNS, Style): the same eight outputs
    boolean rsr = setup != null && setup.selection() == Selection.RSR;
    for (int i = 0; i < 8; i++) {
      if (rsr) {
        setUo(ACK1 + i, ackLeftSec[i] > 1e-9);
        ackLeftSec[i] = Math.max(0, ackLeftSec[i] - dtSec);
      } else {
        setUo(ACK1 + i, (pnsSelected >> i & 1) != 0);
      }
    }
    setUo(SNACK, snackLeftSec > 1e-9);
    snackLeftSec = Math.max(0, snackLeftSec - dtSec);
    setUo(20, false);
  }

  /** Whether the arm stands within reference position {@code r}'s tolerance on every joint. */
  public boolean within(ReferencePosition r) {
    return within(c.currentJoints(), r.jointsDeg().stream().mapToDouble(Double::doubleValue).toArray(),
        r.toleranceDeg().stream().mapToDouble(Double::doubleValue).toArray());
  }

  private static boolean within(org.robotrun.program.Position.Joint q, double[] jointsDeg, double[] toleranceDeg) {
    for (int j = 0; j < jointsDeg.length; j++) {
      if (Math.abs(q.element(j + 1) - jointsDeg[j]) > toleranceDeg[j] + 1e-9) {
        return false;
      }
    }
    return true;
  }

  // ================================================================ PLC sequence

  private void stepPlc(double dtSec) {
    List<PlcStep> steps = setup.plc();
    // several steps may pass in one tick when they have no condition and no delay
    for (int guard = 0; guard < steps.size() && plcStep < steps.size(); guard++) {
      PlcStep st = steps.get(plcStep);
      if (Double.isNaN(plcHeldSec)) {
        if (st.waitFor().isPresent()
            && c.registers().bit(plcWaitKind[plcStep], st.waitFor().get().getKey().index()) != st.waitFor().get().getValue()) {
          return;
        }
        plcHeldSec = 0;
      } else {
        plcHeldSec += dtSec;
      }
      if (plcHeldSec + 1e-9 < st.delaySec()) {
        return;
      }
      for (SetBit b : plcSets.get(plcStep)) {
        c.registers().setBit(b.kind(), b.index(), b.on());
      }
      plcStep++;
      plcHeldSec = Double.NaN;
      if (st.delaySec() > 0) {
        return;
      }
    }
  }

  /** Seconds since the controller started (for the PLC panel). */
  public double simSec() {
    return simSec;
  }

  /** Registers of the controller (the PLC panel reads and writes UI/UO through them). */
  Registers registers() {
    return c.registers();
  }
}
