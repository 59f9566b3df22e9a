using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.Simulator.Tests.Soak;

/// <summary>A line that writes given V bytes when it runs past given times, as an executed WRITE would.</summary>
internal sealed class ScriptedLine(PlcMemory memory, params (TimeSpan At, int Offset, byte[] Bytes)[] writes) : ISimulatedLine
{
    public TimeSpan Now { get; private set; }

    public int FramesReceived => 0;

    public int Replies => 0;

    public TimeSpan? NextOutput => null;

    public void RunUntil(TimeSpan until)
    {
        foreach (var (at, offset, bytes) in writes.Where(w => w.At > Now && w.At <= until))
        {
            bytes.CopyTo(memory.V, offset);
        }

        Now = until;
    }

    public void Deliver(ReadOnlySpan<byte> characters)
    {
    }

    public byte[] TakeTransmitted() => [];
}
