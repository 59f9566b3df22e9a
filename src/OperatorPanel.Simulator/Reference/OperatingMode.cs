namespace OperatorPanel.Simulator.Reference;

/// <summary>RUN executes the program (and the handler); STOP hands the port back to PPI.</summary>
public enum OperatingMode
{
    Run,
    Stop,
}
