namespace OperatorPanel.Simulator.Hosting;

/// <summary>What answers as the simulated PLC: the generated handler in the STL interpreter, or the plain C# model.</summary>
public enum SimulationModel
{
    /// <summary>The handler StlGen generates for the station, executed by the STL interpreter (the default).</summary>
    Stl,

    /// <summary>The reference model of docs/protocol-v2.md (Simulator/Reference/ReferencePlc).</summary>
    Reference,
}
