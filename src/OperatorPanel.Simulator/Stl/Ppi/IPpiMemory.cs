using OperatorPanel.Core.Ppi.S7;

namespace OperatorPanel.Simulator.Stl.Ppi;

/// <summary>What the CPU's PPI side acts on in its communication phase: the memory the program runs on, and its mode.</summary>
public interface IPpiMemory
{
    S7ItemResult Read(S7Item item);

    S7ReturnCode Write(S7WriteItem item);

    /// <summary>STOP or RUN asked over PPI; false when the CPU refuses (e.g. RUN with a fault pending).</summary>
    bool Control(S7Function function);
}
