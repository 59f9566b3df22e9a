using OperatorPanel.Core.Cpu;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Tests.V3;

/// <summary>
/// The technician notes promise that the handler adds at most 2 ms to any one scan (docs/protocol.md section 6; issue
/// 23), at the StlTiming figures of the interpreter (simulated time, not the clock). `generate --stats` measures READ,
/// WRITE and WRITE BITS in every area and keeps the slowest: the item check finds the area by tests in turn, and
/// before 2026-11-28 the measurement tried V only, the first area tested, while a 16-byte WRITE to SMB0 added 2.41 ms
/// to its dispatch scan (full handler) and 2.12 ms (compact).
/// </summary>
public sealed class V3ScanShareTests
{
    private static readonly TimeSpan ScanShare = TimeSpan.FromMilliseconds(2);

    [Theory]
    [InlineData(CpuModel.Cpu224, false)]
    [InlineData(CpuModel.Cpu226, false)]
    [InlineData(CpuModel.Cpu221, true)]
    [InlineData(CpuModel.Cpu222, true)]
    public void EveryMeasuredRequest_InItsSlowestArea_AddsAtMostTwoMillisecondsToAScan(CpuModel model, bool compact)
    {
        // STOP where the handler can have it: the compact one has none (STL031).
        var options = new HandlerOptions { Cpu = CpuProfiles.For(model), Station = 2, AllowStop = !compact, Protocol = 3, Compact = compact };
        var requests = V3Measured.Requests(options);

        requests.Where(r => r.Name.StartsWith("READ 16", StringComparison.Ordinal) || r.Name.StartsWith("WRITE", StringComparison.Ordinal))
            .Select(r => r.Name).Should().HaveCount(3).And.OnlyContain(n => System.Text.RegularExpressions.Regex.IsMatch(n, @", (I|Q|M|V|SM)B\d+$"), "each item row names the area it was slowest in");
        foreach (var request in requests)
        {
            request.WorstScan.Should().BeLessThanOrEqualTo(ScanShare, request.Name);
        }
    }
}
