/**
 * TP programs: the model, registers and the interpreter. Pure Java; imports only
 * {@code org.robotrun.math}. The robot is reached through an interface this package owns.
 *
 * <h2>Model</h2>
 *
 * <ul>
 *   <li>{@link org.robotrun.program.Program}: name, /ATTR entries (ordered, raw text), comment,
 *       the /MN lines as {@link org.robotrun.program.Instruction} records (one per numbered line,
 *       one record type per statement of TP-LANGUAGE.md) and the /POS block as
 *       {@link org.robotrun.program.LocalPosition}s.
 *   <li>{@link org.robotrun.program.Expr}: expressions as written, parentheses kept as
 *       {@code Group}; operators carry their TP spelling and precedence.
 *   <li>{@link org.robotrun.program.Motion}: motion parts (type, target, speed, termination,
 *       options).
 *   <li>{@link org.robotrun.program.Item}, {@link org.robotrun.program.Index},
 *       {@link org.robotrun.program.LabelRef}: numbered references, direct or indirect
 *       ({@code R[R[i]]}), with their item comments so a round trip is lossless.
 *   <li>{@link org.robotrun.program.Position}: Cartesian (mm, deg, CONFIG) or joint (deg), shared
 *       by local positions and position registers.
 *   <li>{@link org.robotrun.program.Registers}: the mutable register and I/O state.
 * </ul>
 *
 * <p>Parsing and printing live in {@code org.robotrun.io} (LsReader / LsWriter); nothing here
 * reads or writes text.
 */
package org.robotrun.program;
