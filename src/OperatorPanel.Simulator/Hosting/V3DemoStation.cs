using OperatorPanel.Simulator.Reference;
using OperatorPanel.Simulator.Reference.V3;

namespace OperatorPanel.Simulator.Hosting;

/// <summary>
/// A protocol v3 reference station (<see cref="ReferenceHandler"/>) as the demo process sees a CPU: its memory, its
/// mode, the scan times it reports in SMW22-SMW26 (seed 002 Table C-9), and the outputs the panel took over. An output
/// a message changed (a panel WRITE or WRITE BITS) stays the panel's, as the STL station keeps it
/// (<see cref="StlStation"/>): the model itself keeps no such record, so this compares Q around each message.
/// </summary>
public sealed class V3DemoStation : IDemoPlc
{
    private readonly byte[] _panelOutputs;
    private readonly ScanTimes _scanTimes = new();

    public V3DemoStation(ReferenceHandler handler)
    {
        ArgumentNullException.ThrowIfNull(handler);
        Handler = handler;
        _panelOutputs = new byte[handler.Memory.Q.Length];
    }

    public ReferenceHandler Handler { get; }

    public PlcMemory Memory => Handler.Memory;

    public OperatingMode Mode => Handler.Mode;

    /// <summary>The model's reply to <paramref name="message"/> (null: silence); outputs it changed become the panel's.</summary>
    public byte[]? HandleMessage(ReadOnlySpan<byte> message)
    {
        byte[] before = [.. Memory.Q];
        var reply = Handler.HandleMessage(message);
        var q = Memory.Q;
        for (var i = 0; i < q.Length; i++)
        {
            _panelOutputs[i] |= (byte)(q[i] ^ before[i]);
        }

        return reply;
    }

    public void CompleteScan(ushort milliseconds) => _scanTimes.Record(Memory, milliseconds);

    public bool IsOwnedByPanel(int offset, int bit) => (_panelOutputs[offset] & (1 << bit)) != 0;
}
