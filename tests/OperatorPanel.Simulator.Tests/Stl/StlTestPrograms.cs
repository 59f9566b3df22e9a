using OperatorPanel.Core.Cpu;
using OperatorPanel.Simulator.Stl;

namespace OperatorPanel.Simulator.Tests.Stl;

/// <summary>Builds small .awl programs around an OB1 body and loads them for a CPU 224 (or the CPU given).</summary>
internal static class StlTestPrograms
{
    public static string Text(string body, string blocks = "") =>
        "ORGANIZATION_BLOCK MAIN:OB1\r\nBEGIN\r\nNetwork 1\r\n" + body.Replace("\n", "\r\n", StringComparison.Ordinal).Replace("\r\r", "\r", StringComparison.Ordinal)
        + "\r\nEND_ORGANIZATION_BLOCK\r\n" + blocks;

    public static StlPlc Plc(string body, string blocks = "", CpuModel model = CpuModel.Cpu224)
    {
        var result = StlProgramLoader.Load(Text(body, blocks), CpuProfiles.For(model));
        result.Diagnostics.Should().BeEmpty();
        return new StlPlc(result.Program!);
    }

    /// <summary>Runs exactly one scan (OB1 once) from power-up.</summary>
    public static StlPlc OneScan(string body, string blocks = "")
    {
        var plc = Plc(body, blocks);
        plc.RunUntil(TimeSpan.FromTicks(1));
        while (plc.Scans == 1 && plc.Mode == OperatorPanel.Simulator.Reference.OperatingMode.Run)
        {
            plc.RunUntil(plc.Now + TimeSpan.FromTicks(1));
            if (plc.Now > TimeSpan.FromMilliseconds(1000))
            {
                break;
            }
        }

        return plc;
    }
}
