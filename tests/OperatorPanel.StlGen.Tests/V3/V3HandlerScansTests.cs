using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link.V3;
using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.Simulator.Handlers;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Tests.V3;

/// <summary>
/// The panel's reply time-outs count a v3 handler's scans per command (<see cref="V3HandlerScans"/>, Core); the
/// generated handler measured in the interpreter, as `generate --stats` measures it, must never need more, or the panel
/// would give up on a reply still coming (and settle a write by read-back that was about to be confirmed).
/// </summary>
public sealed class V3HandlerScansTests
{
    [Theory]
    [InlineData(CpuModel.Cpu221)]
    [InlineData(CpuModel.Cpu224)]
    [InlineData(CpuModel.Cpu226)]
    public void GeneratedFullHandler_EveryMeasuredRequest_TakesNoMoreScansThanThePanelAllows(CpuModel model)
    {
        var options = new HandlerOptions { Cpu = CpuProfiles.For(model), Station = 2, AllowStop = true, Protocol = 3 };
        var requests = V3Measured.Requests(options);

        var measured = requests.Where(r => r.Name != V3Measurement.IdleName).ToList();
        measured.Select(r => CommandOf(r.Name)).Should().Contain([Command.Identify, Command.Read, Command.Write, Command.WriteBits,
            Command.DefineList, Command.ReadList, Command.ReadListFull]);
        foreach (var request in measured)
        {
            request.Scans.Should().BeLessThanOrEqualTo(V3HandlerScans.For(CommandOf(request.Name)), request.Name);
        }
    }

    /// <summary>The command of a `--stats` row by its name (V3Measurement's names; silence rows as READ).</summary>
    private static Command CommandOf(string name) => name switch
    {
        _ when name.StartsWith("IDENTIFY", StringComparison.Ordinal) => Command.Identify,
        _ when name.StartsWith("WRITE BITS", StringComparison.Ordinal) => Command.WriteBits,
        _ when name.StartsWith("WRITE", StringComparison.Ordinal) => Command.Write,
        _ when name.StartsWith("DEFINE LIST", StringComparison.Ordinal) => Command.DefineList,
        _ when name.Contains("READ LIST FULL", StringComparison.Ordinal) => Command.ReadListFull,
        _ when name.Contains("READ LIST", StringComparison.Ordinal) => Command.ReadList,
        _ => Command.Read,
    };
}
