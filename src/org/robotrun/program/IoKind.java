package org.robotrun.program;

/**
 * Bit, group and analog I/O plus flags, indexed from 1 up to the controller's configured size
 * ({@link IoRanges}: by default DI/DO 512, RI/RO 8, GI/GO 100, flags 200, SI/SO 15, AI/AO 64). Inputs (DI, RI, GI) are set
 * by the simulation (RI[1] reports the gripper closed); outputs (DO, RO, GO) and flags (F) are
 * written by programs. RO[1] drives the end effector unless a scenario maps it otherwise.
 */
public enum IoKind {
  DI(false, false), DO(true, false), RI(false, false), RO(true, false), GI(false, true), GO(true, true), F(true, false),
  /** Standard operator panel inputs (SOP), read-only for a program. */
  SI(false, false),
  /** Standard operator panel outputs (SOP): set by the controller, read by a program. */
  SO(false, false),
  /** Analog inputs: an integer value (the converter's digital value). */
  AI(false, true),
  /** Analog outputs: a program sets an integer value. */
  AO(true, true),
  /** UOP inputs UI[1..18] (*IMSTP, *HOLD, ... PROD_START): set by the PLC, read by programs (sim.Uop). */
  UI(false, false),
  /** UOP outputs UO[1..20] (CMDENBL, SYSRDY, PROGRUN ...): set by the controller, read by programs (sim.Uop). */
  UO(false, false);

  private final boolean writable;
  private final boolean group;

  IoKind(boolean writable, boolean group) {
    this.writable = writable;
    this.group = group;
  }

  /** Whether a program may assign it ({@code DO[1]=ON}); inputs are written only by the simulation. */
  public boolean writable() {
    return writable;
  }

  /** Group and analog ports (GI, GO, AI, AO) carry an integer; the others ON/OFF. */
  public boolean group() {
    return group;
  }

  /** Highest valid index with the default ranges ({@link IoRanges#DEFAULT}); a controller may be configured otherwise. */
  public int size() {
    return IoRanges.DEFAULT.size(this);
  }
}
