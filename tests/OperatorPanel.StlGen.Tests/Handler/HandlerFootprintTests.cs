using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Transport;
using OperatorPanel.StlGen.Options;
using OperatorPanel.StlGen.Tests.Golden;

namespace OperatorPanel.StlGen.Tests.Handler;

/// <summary>
/// Issue 4, "Proof": every generated program uses only addresses inside the chosen CPU's ranges and only the V bytes,
/// SBR/INT numbers and events it says it reserves, read with the Core parser (<see cref="HandlerFootprintAudit"/>).
/// </summary>
public sealed class HandlerFootprintTests
{
    private static readonly int[] WriteMasks = [HandlerDefaults.WriteMask, 0x00, 0x24];

    private static readonly int[] CharTimeouts = [0, 100];

    private static readonly HandlerBlockNames Renamed = new() { Panel = "PNL_SBR", Receive = "PNL_RX", Delay = "PNL_WAIT", Transmit = "PNL_TX" };

    public static TheoryData<CpuModel, CpuRevision, int> EveryCpuAndPort()
    {
        var data = new TheoryData<CpuModel, CpuRevision, int>();
        foreach (var cpu in CpuProfiles.All)
        {
            for (var port = 0; port < cpu.CommunicationPorts; port++)
            {
                data.Add(cpu.Model, cpu.Revision, port);
            }
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(EveryCpuAndPort))]
    public void Generate_EveryOptionCombination_StaysInsideWhatItReserves(CpuModel model, CpuRevision revision, int port)
    {
        var cpu = CpuProfiles.For(model, revision);
        var combinations = Combinations(cpu, port).ToList();

        var problems = combinations.SelectMany(o => HandlerFootprintAudit.Problems(o).Select(p => $"{Describe(o)}: {p}")).ToList();

        combinations.Should().HaveCount(72);
        problems.Should().BeEmpty();
    }

    [Theory]
    [InlineData("MOVB   5, SMB34", "MOVB   5, SMB35", "SMB35, not a byte the handler reserves")]
    [InlineData("MOVB   5, SMB34", "MOVB   5, SMB550", "SMB550 is past the last SM byte SMB549")]
    [InlineData("MOVB   16#E0, SMB87", "MOVB   16#E0, SMB29", "read-only system status bytes")]
    [InlineData("XMT    *AC1, 0", "XMT    *AC1, 1", "not on port 0")]
    [InlineData("DTCH   9\r\n", "DTCH   26\r\n", "events")]
    [InlineData("MOVD   &VB8027, AC3", "MOVD   &VB7763, AC3", "VB7763-VB7763 outside VB7764-VB8191")]
    [InlineData("MOVD   &VB8027, AC3", "MOVD   &IB4, AC3", "a pointer outside V")]
    [InlineData("CALL   OP_PANEL", "CALL   SBR_0", "not the handler's subroutine")]
    [InlineData("ATCH   OP_TX, 9", "ATCH   OP_TX, 8", "not the routine's event 9")]
    [InlineData("SLW    AC0, 3", "SHLW   AC0, 3", "AWL001 SHLW is not an S7-200 STL instruction")]
    [InlineData("SLW    AC0, 3", "SLW    VB1, 3", "AWL008 SLW: 'VB1' is a byte; OUT is a WORD")]
    [InlineData("ATCH   OP_TX, 9", "ATCH   OP_TX, 26", "AWL006 ATCH: the CPU 224 has no interrupt event 26")]
    [InlineData("CRETI", "RETI", "AWL002 RETI is not written in STL")]
    public void Audit_TamperedHandler_ReportsTheProblem(string original, string tampered, string expected)
    {
        var options = HandlerGoldenTests.Cpu224Port0Station2;
        HandlerGenerator.Generate(options).AwlText.Should().Contain(original);

        var problems = HandlerFootprintAudit.Problems(options, text => text.Replace(original, tampered, StringComparison.Ordinal));

        problems.Should().Contain(p => p.Contains(expected, StringComparison.Ordinal));
    }

    [Fact]
    public void Audit_UntouchedHandler_ReportsTheReservedBytesAndEvents()
    {
        var problems = HandlerFootprintAudit.Problems(HandlerGoldenTests.Cpu226Port1Station17);

        problems.Should().BeEmpty();
        HandlerGenerator.Generate(HandlerGoldenTests.Cpu226Port1Station17).Stats!.Blocks.Select(b => b.NumberText)
            .Should().Equal("SBR127", "INT125", "INT126", "INT127");
    }

    /// <summary>4 buffers x 3 block placements x 3 write masks x 2 char timeouts; baud, parity, data bits and station vary along.</summary>
    private static IEnumerable<HandlerOptions> Combinations(CpuProfile cpu, int port)
    {
        cpu.TryGetArea(MemoryArea.V, out var v).Should().BeTrue();
        int?[] buffers = [null, 0, 1001, v.ByteCount - HandlerDefaults.FootprintBytes(HandlerDefaults.CopyBytes)];
        (int? Sbr, int? Int, HandlerBlockNames Names)[] blocks =
            [(null, null, new HandlerBlockNames()), (0, 0, new HandlerBlockNames()), (cpu.Subroutines / 2, 40, Renamed)];
        var rates = cpu.FreeportBaudRates;
        var n = 0;
        foreach (var buffer in buffers)
        {
            foreach (var (sbr, first, names) in blocks)
            {
                foreach (var mask in WriteMasks)
                {
                    foreach (var timeout in CharTimeouts)
                    {
                        n++;
                        yield return new HandlerOptions
                        {
                            Protocol = 2,
                            Cpu = cpu,
                            Port = port,
                            BaudRate = rates[n % rates.Length].Baud,
                            Parity = (Parity)(n % 3),
                            DataBits = 7 + (n % 2),
                            Station = 1 + (n * 7 % 126),
                            BufferStart = buffer,
                            FirstSubroutine = sbr,
                            FirstInterrupt = first,
                            Names = names,
                            WriteMask = mask,
                            CharTimeoutMs = timeout,
                            ReplyDelayMs = 1 + (n % 255),
                        };
                    }
                }
            }
        }
    }

    private static string Describe(HandlerOptions o) =>
        $"{o.Cpu.DisplayName} port {o.Port} {o.BaudRate} buffer {o.BufferStart?.ToString(System.Globalization.CultureInfo.InvariantCulture) ?? "default"} SBR {o.EffectiveFirstSubroutine} INT {o.EffectiveFirstInterrupt} mask 16#{o.WriteMask:X2} timeout {o.CharTimeoutMs}";
}
