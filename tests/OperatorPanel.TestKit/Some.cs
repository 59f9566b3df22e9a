using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.TestKit;

/// <summary>
/// Valid values for tests that do not care which (Serilog's Some.* builders). Stations differ from call to call, so a
/// test cannot pass by accident on a shared default.
/// </summary>
public static class Some
{
    private static int _counter;

    /// <summary>A station 1-126, different on each call (cycling).</summary>
    public static Station Station() => new((Next() % Core.Addressing.Station.Max) + 1);

    /// <summary>A CPU profile; CPU 224 Current (the most common one) unless the test names another.</summary>
    public static CpuProfile Cpu(CpuModel model = CpuModel.Cpu224, CpuRevision revision = CpuRevision.Current) =>
        CpuProfiles.For(model, revision);

    /// <summary>Serial settings for a port that tests never open.</summary>
    public static SerialSettings SerialSettings(int baudRate = 9600, LinkKind kind = LinkKind.Cable) =>
        new() { PortName = "/dev/ttyTEST" + Next(), BaudRate = baudRate, Kind = kind };

    private static int Next() => Interlocked.Increment(ref _counter);
}
