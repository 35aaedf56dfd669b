package org.robotrun.collision;

/** Two bodies whose boxes overlap or touch. */
public record Contact(Body a, Body b) {}
