using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Simulator.Reference;

/// <summary>One bit of the demo line's symbol table (samples/bottling-line.opproj), e.g. I0.5 InfeedBottle.</summary>
internal readonly record struct DemoBit(ProtocolArea Area, int Offset, int Bit)
{
    public bool Get(PlcMemory memory) => memory.GetBit(Area, Offset, Bit);

    public void Set(PlcMemory memory, bool value) => memory.SetBit(Area, Offset, Bit, value);
}
