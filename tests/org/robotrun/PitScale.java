package org.robotrun;

import net.jqwik.api.lifecycle.AroundPropertyHook;
import net.jqwik.api.lifecycle.PropertyExecutionResult;
import net.jqwik.api.lifecycle.PropertyExecutor;
import net.jqwik.api.lifecycle.PropertyLifecycleContext;

/**
 * Smaller samples under mutation testing only. The mutation profile (pom.xml, {@code -Pmutation})
 * sets {@code -Drobotrun.pit=true} in PIT's test workers: there every surviving mutant reruns each
 * covering test, so the sweeps of thousands of random targets that {@code ./mvnw verify} runs once
 * would be rerun thousands of times. Under PIT a sweep takes its smaller sample (the same seeds, the
 * first N of the same sequence), and jqwik properties of classes that add {@link Tries} run at most
 * {@link #PIT_TRIES} tries. Without the property (surefire, the IDE) everything keeps its full size.
 */
public final class PitScale {
  /** jqwik tries per property under PIT (verify keeps each property's own tries). */
  public static final int PIT_TRIES = 100;

  private PitScale() {}

  /** True inside PIT's test workers. */
  public static boolean underPit() {
    return Boolean.getBoolean("robotrun.pit");
  }

  /** {@code full} normally, {@code underPit} under mutation testing. */
  public static int samples(int full, int underPit) {
    return underPit() ? Math.min(full, underPit) : full;
  }

  /**
   * A jqwik hook ({@code @AddLifecycleHook(PitScale.Tries.class)} on a test class) that caps each
   * property's tries at {@link #PIT_TRIES} under PIT and leaves them alone otherwise.
   */
  public static final class Tries implements AroundPropertyHook {
    @Override
    public PropertyExecutionResult aroundProperty(PropertyLifecycleContext context, PropertyExecutor property) {
      if (underPit()) {
        int tries = context.attributes().tries().orElse(PIT_TRIES);
        context.attributes().setTries(Math.min(tries, PIT_TRIES));
      }
      return property.execute();
    }

    @Override
    public net.jqwik.api.lifecycle.PropagationMode propagateTo() {
      return net.jqwik.api.lifecycle.PropagationMode.ALL_DESCENDANTS; // added on a class: reach its properties
    }

    @Override
    public int aroundPropertyProximity() {
      return -100; // outermost: the tries are read when the property starts, inside this hook
    }
  }
}
