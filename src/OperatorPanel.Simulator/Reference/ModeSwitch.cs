namespace OperatorPanel.Simulator.Reference;

/// <summary>
/// The mode switch in the positions a running CPU can have. SM0.7 is on at RUN, off at TERM; the handler keeps
/// Freeport only while SM0.7 is on, so TERM gives the port back to the programming device (seed 002, Table C-1).
/// </summary>
public enum ModeSwitch
{
    Run,
    Term,
}
