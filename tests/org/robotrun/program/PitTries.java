package org.robotrun.program;

import net.jqwik.api.lifecycle.AroundPropertyHook;
import net.jqwik.api.lifecycle.PropagationMode;
import net.jqwik.api.lifecycle.PropertyExecutionResult;
import net.jqwik.api.lifecycle.PropertyExecutor;
import net.jqwik.api.lifecycle.PropertyLifecycleContext;

/**
 * Caps a property's tries at the system property {@code robotrun.pit.tries} when it is set: the
 * mutation profile (pom.xml, {@code -Pmutation}) sets it for the program and sim sets, so a
 * property that covers a mutant costs a few hundred tries there instead of thousands. Unset (the
 * normal build), a property runs the tries its annotation names. Use with
 * {@code @AddLifecycleHook(PitTries.class)}.
 */
public final class PitTries implements AroundPropertyHook {

  /** Put on a test class, it reaches every property in it. */
  @Override
  public PropagationMode propagateTo() {
    return PropagationMode.ALL_DESCENDANTS;
  }

  @Override
  public PropertyExecutionResult aroundProperty(PropertyLifecycleContext context, PropertyExecutor property) {
    Integer cap = Integer.getInteger("robotrun.pit.tries");
    if (cap != null) {
      int tries = context.attributes().tries().orElse(1000);
      if (tries > cap) {
        context.attributes().setTries(cap);
      }
    }
    return property.execute();
  }
}
