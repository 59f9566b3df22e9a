using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Simulator.Reference;

/// <summary>
/// A simulated CPU's scan times in SMW22 (last), SMW24 (shortest) and SMW26 (longest since RUN; seed 002 Table C-9),
/// kept as each demo scan ends: one recorder per CPU model that reports them (v2's and v3's reference models).
/// </summary>
public sealed class ScanTimes
{
    private const int Smw22 = 22;
    private bool _scanned;

    /// <summary>Records one finished scan of <paramref name="milliseconds"/> in <paramref name="memory"/>'s SMW22-SMW26.</summary>
    public void Record(PlcMemory memory, ushort milliseconds)
    {
        ArgumentNullException.ThrowIfNull(memory);
        var min = memory.ReadWord(ProtocolArea.SM, Smw22 + 2);
        var max = memory.ReadWord(ProtocolArea.SM, Smw22 + 4);
        memory.WriteWord(ProtocolArea.SM, Smw22, milliseconds);
        memory.WriteWord(ProtocolArea.SM, Smw22 + 2, _scanned ? Math.Min(min, milliseconds) : milliseconds);
        memory.WriteWord(ProtocolArea.SM, Smw22 + 4, _scanned ? Math.Max(max, milliseconds) : milliseconds);
        _scanned = true;
    }
}
