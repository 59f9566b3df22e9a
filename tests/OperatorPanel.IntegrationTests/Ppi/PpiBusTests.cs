using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Transport;
using OperatorPanel.Core.Writes;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Stl.Freeport;
using OperatorPanel.Simulator.Stl.Ppi;

namespace OperatorPanel.IntegrationTests.Ppi;

/// <summary>
/// A PPI bus behind the one bus owner (Line/Bus.StartPpi): the PPI reader and writer chosen for every station, the
/// plan of Polling/PpiPollPlanner, over a simulated S7-200 with no handler, in the line's own time
/// (<see cref="SimulatedLineTransport"/>: no real time passes on the wire).
/// </summary>
public sealed class PpiBusTests
{
    private static readonly LineSettings PpiLine = new(9600, Parity.Even, 8);
    private static readonly Station Cpu2 = new(2);

    [Fact]
    public async Task Refresh_NoHandlerLoaded_ReadsEveryValueGood()
    {
        var (line, station) = Create();
        station.Memory.V[100] = 0x42;
        station.Plc.InputImage[0] = 0x01;
        (station.Memory.M[4], station.Memory.M[5]) = (0x12, 0x34);
        await using var bus = Start(line, "VB100", "I0.0", "MW4");

        await bus.RefreshAsync();

        Value(bus, "VB100").Should().Be("42 Good");
        Value(bus, "I0.0").Should().Be("01 Good");
        Value(bus, "MW4").Should().Be("1234 Good");
        bus.StatusOf(Cpu2).State.Should().Be(StationState.Online);
        bus.PpiCounters!.Jobs.Should().Be(1, "three addresses fit one read job");
    }

    [Fact]
    public async Task Refresh_AnalogSBitsTimersAndCounters_ReadFromTheMemoryTheProgramRunsOn()
    {
        var (line, station) = Create(ValuesProgram.Awl);
        (station.Plc.AreaBytes(MemoryArea.AI)[0], station.Plc.AreaBytes(MemoryArea.AI)[1]) = (0x12, 0x34);
        station.Plc.AreaBytes(MemoryArea.S)[0] = 0x81;
        await using var bus = Start(line, "AIW0", "AQW0", "SB0", "S0.7", "T37", "C5", "VB100");

        await bus.RefreshAsync();

        Value(bus, "AIW0").Should().Be("1234 Good");
        Value(bus, "AQW0").Should().Be("04D2 Good", "MOVW 1234, AQW0");
        Value(bus, "SB0").Should().Be("81 Good");
        Value(bus, "S0.7").Should().Be("01 Good");
        Value(bus, "T37").Should().Be("00FA Good", "MOVW 250, T37");
        Value(bus, "C5").Should().Be("FFF9 Good", "MOVW -7, C5: the current value is a signed word");
        bus.PpiCounters!.Jobs.Should().Be(1, "one job carries the byte, word, timer and counter items");
    }

    [Fact]
    public async Task Write_AnalogOutputAndSBit_ConfirmedByReadBack_AnalogInputAndTimerRefusedBeforeSending()
    {
        var (line, station) = Create();
        await using var bus = Start(line, "AQW2", "S1.3", "AIW0", "T37");

        var aq = await bus.WriteAsync(WriteRequest.Bytes(Cpu2, PlcAddress.Parse("AQW2"), [0x01, 0x02]));
        var s = await bus.WriteAsync(WriteRequest.Bit(Cpu2, PlcAddress.Parse("S1.3"), true));
        var ai = await bus.WriteAsync(WriteRequest.Bytes(Cpu2, PlcAddress.Parse("AIW0"), [0x00, 0x01]));
        var timer = await bus.WriteAsync(WriteRequest.Bytes(Cpu2, PlcAddress.Parse("T37"), [0x00, 0x01]));

        aq.Should().BeOfType<WriteOutcome.Confirmed>();
        s.Should().BeOfType<WriteOutcome.Confirmed>();
        (station.Plc.AreaBytes(MemoryArea.AQ)[2], station.Plc.AreaBytes(MemoryArea.AQ)[3], station.Plc.AreaBytes(MemoryArea.S)[1]).Should().Be(((byte)1, (byte)2, (byte)0x08));
        ai.Should().BeOfType<WriteOutcome.Failed>().Which.Reason.Should().Be("AIW0: analog inputs are read-only");
        timer.Should().BeOfType<WriteOutcome.Failed>().Which.Reason.Should().StartWith("T37: the panel reads timer current values but never writes them");
        Value(bus, "AQW2").Should().Be("0102 Good", "the read-back goes to the value store");
    }

    [Fact]
    public async Task Refresh_ItemRefusedByTheCpu_OnlyItsValueIsBadWithTheCodesText()
    {
        var (line, station) = Create();
        station.Memory.V[100] = 0x42;
        await using var bus = Start(line, "VB100", "VB30000");

        await bus.RefreshAsync();

        Value(bus, "VB100").Should().Be("42 Good");
        bus.TryGetValue(Cpu2, PlcAddress.Parse("VB30000"), out var refused).Should().BeTrue();
        refused.Quality.Should().Be(ValueQuality.Bad);
        refused.Error.Should().Contain("beyond the CPU's memory (16#05)");
        bus.StatusOf(Cpu2).State.Should().Be(StationState.Online, "a refused item is an answer");
    }

    [Fact]
    public async Task Refresh_CpuInStop_StillReads()
    {
        var (line, station) = Create();
        station.Memory.V[100] = 0x07;
        station.Plc.Stop();
        await using var bus = Start(line, "VB100");

        await bus.RefreshAsync();

        Value(bus, "VB100").Should().Be("07 Good");
    }

    [Fact]
    public async Task Refresh_NoCpuAtTheAddress_StationOfflineValueBad()
    {
        var (line, _) = Create();
        await using var bus = Start(line, new Station(5), "VB100");

        await bus.RefreshAsync();

        var status = bus.StatusOf(new Station(5));
        status.State.Should().Be(StationState.Offline);
        status.LastErrorKind.Should().Be(PlcErrorKind.NoAnswer);
        bus.TryGetValue(new Station(5), PlcAddress.Parse("VB100"), out var value).Should().BeTrue();
        value.Quality.Should().Be(ValueQuality.Bad);
    }

    [Fact]
    public async Task Write_WordAndBit_ConfirmedByReadBackAndInTheValues()
    {
        var (line, station) = Create();
        station.Memory.Q[0] = 0x01;
        await using var bus = Start(line, "MW4", "Q0.3");
        await bus.RefreshAsync();

        var word = await bus.WriteAsync(WriteRequest.Bytes(Cpu2, PlcAddress.Parse("MW4"), [0xBE, 0xEF]));
        var bit = await bus.WriteAsync(WriteRequest.Bit(Cpu2, PlcAddress.Parse("Q0.3"), true));

        word.Should().BeOfType<WriteOutcome.Confirmed>().Which.ReadBack.Should().Equal(0xBE, 0xEF);
        bit.Should().BeOfType<WriteOutcome.Confirmed>().Which.ReadBack.Should().Equal(0x01);
        (station.Memory.M[4], station.Memory.M[5], station.Memory.Q[0]).Should().Be(((byte)0xBE, (byte)0xEF, (byte)0x09), "a bit item leaves Q0.0 alone");
        Value(bus, "MW4").Should().Be("BEEF Good");
        Value(bus, "Q0.3").Should().Be("01 Good");
    }

    [Fact]
    public async Task ReadsAndWrites_OnOneBus_NumberedFromOneSequenceOfReferences()
    {
        var (line, _) = Create();
        var transport = new JobRecorder(new SimulatedLineTransport(line));
        var plan = PpiPollPlanner.Build(((string[])["VB10", "Q0.1", "VW200", "VD300"]).Select(a => new WatchedItem(Cpu2, PlcAddress.Parse(a))));
        await using var bus = Bus.StartPpi(new PpiLink(transport, PpiMasterOptions.ForBaud(9600) with { FirstReference = 1 }, transport.Inner.Clock), plan, BusSettings.OnDemand, transport.Inner.Clock);

        await bus.RefreshAsync();
        var byteWrite = await bus.WriteAsync(WriteRequest.Bytes(Cpu2, PlcAddress.Parse("VB10"), [0x05]));
        var bitWrite = await bus.WriteAsync(WriteRequest.Bit(Cpu2, PlcAddress.Parse("Q0.1"), true));
        var wordWrite = await bus.WriteAsync(WriteRequest.Bytes(Cpu2, PlcAddress.Parse("VW200"), [0x04, 0xD2]));
        await bus.RefreshAsync();

        byteWrite.Should().BeOfType<WriteOutcome.Confirmed>();
        bitWrite.Should().BeOfType<WriteOutcome.Confirmed>();
        wordWrite.Should().BeOfType<WriteOutcome.Confirmed>();
        transport.Jobs.Should().Equal(
            "read 1", "write 2", "read 3", "write 4", "read 5", "write 6", "read 7", "read 8");
    }

    [Fact]
    public async Task Write_AddressTheCpuRefuses_FailedWithTheCodesText()
    {
        var (line, _) = Create();
        await using var bus = Start(line, "VB100");

        var outcome = await bus.WriteAsync(WriteRequest.Bytes(Cpu2, PlcAddress.Parse("VB30000"), [0x01]));

        var failed = outcome.Should().BeOfType<WriteOutcome.Failed>().Which;
        failed.Kind.Should().Be(WriteFailureKind.RefusedByPlc);
        failed.Reason.Should().Contain("16#05");
    }

    [Fact]
    public async Task Write_InputArea_RefusedBeforeSending()
    {
        var (line, _) = Create();
        await using var bus = Start(line, "VB100");

        var outcome = await bus.WriteAsync(WriteRequest.Bit(Cpu2, PlcAddress.Parse("I0.0"), true));

        outcome.Should().BeOfType<WriteOutcome.Failed>().Which.Kind.Should().Be(WriteFailureKind.InvalidRequest);
        bus.PpiCounters!.Jobs.Should().Be(0);
    }

    [Fact]
    public async Task IdentifyPpi_Cpu224_ReadsSmb6SwitchAndScanTimes()
    {
        var (line, station) = Create();
        await using var bus = Start(line, "VB100");

        var outcome = await bus.IdentifyPpiAsync(Cpu2);

        outcome.Error.Should().BeNull();
        var identity = outcome.Identity!;
        identity.Smb6.Should().Be(CpuProfiles.For(CpuModel.Cpu224).CpuIdCode);
        identity.SwitchAtRun.Should().BeTrue();
        identity.LastScanMs.Should().Be((station.Memory.SM[22] << 8) | station.Memory.SM[23]);
    }

    [Fact]
    public async Task FreeportRequests_OnAPpiBus_FailBeforeAnythingIsSent()
    {
        var (line, _) = Create();
        await using var bus = Start(line, "VB100");

        var reply = await bus.IdentifyAsync(Cpu2);
        var stop = await bus.StopAsync(Cpu2);

        reply.Failure!.Message.Should().Contain("is a PPI bus");
        stop.Verdict.Should().Be(Core.Stop.StopVerdict.NotSent);
        bus.PpiCounters!.Jobs.Should().Be(0);
    }

    [Theory]
    [InlineData(0x04, 0xD2, UnfinishedWrites.Applied, "the PLC holds the requested 16#04D2")]
    [InlineData(0x00, 0x07, UnfinishedWrites.NotApplied, "the PLC still holds the old 16#0007")]
    public async Task SettleCutShort_WriteLeftOpenOnAPpiBus_IsReadBackWithAnS7ReadJob(byte high, byte low, string outcome, string detail)
    {
        var (line, station) = Create();
        (station.Plc.AreaBytes(MemoryArea.AQ)[2], station.Plc.AreaBytes(MemoryArea.AQ)[3]) = (high, low);
        var folder = Path.Combine(Path.GetTempPath(), "opanel-ppi-settle-" + Guid.NewGuid().ToString("N"));
        try
        {
            var journal = WriteJournal.In(folder);
            var intent = new AuditEntry(Guid.NewGuid(), AuditStep.Intent, AuditAction.Write, DateTimeOffset.UnixEpoch, "root", "simulated line", Cpu2, "AQW2", null, "16#0007", "16#04D2");
            Directory.CreateDirectory(folder);
            File.WriteAllLines(journal.Path, [new JournalLine(intent, EndedProcessId(), DateTimeOffset.UnixEpoch).Format()]);
            await using var bus = Start(line, "VB100");

            var (resolved, problem) = await bus.SettleCutShortAsync(journal);

            problem.Should().BeNull();
            resolved.Should().ContainSingle().Which.Resolution.Should().Match<AuditEntry>(e => e.Outcome == outcome && e.Detail == detail);
            bus.PpiCounters!.Jobs.Should().Be(1, "one S7 read job, no Freeport frame and no second write");
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }

    /// <summary>The id of a process that has ended: the journal settles only what a program no longer running left open.</summary>
    private static int EndedProcessId()
    {
        using var process = System.Diagnostics.Process.Start(new System.Diagnostics.ProcessStartInfo("true") { UseShellExecute = false })!;
        process.WaitForExit();
        return process.Id;
    }

    private static (StlLine Line, StlStation Station) Create(string awl = EmptyProgram.Awl)
    {
        var line = new StlLine(PpiLine);
        StlStation.TryCreate(awl, CpuProfiles.For(CpuModel.Cpu224), 0, PpiLine, out var station, out var error).Should().BeTrue(error);
        station!.AttachPpi(new PpiSettings(2, 9600));
        line.Attach(station, runProcess: false);
        line.RunUntil(TimeSpan.FromMilliseconds(50));
        return (line, station);
    }

    private static Bus Start(StlLine line, params string[] addresses) => Start(line, Cpu2, addresses);

    private static Bus Start(StlLine line, Station station, params string[] addresses)
    {
        var transport = new SimulatedLineTransport(line);
        var plan = PpiPollPlanner.Build(addresses.Select(a => new WatchedItem(station, PlcAddress.Parse(a))));
        return Bus.StartPpi(new PpiLink(transport, PpiMasterOptions.ForBaud(9600) with { FirstReference = 1 }, transport.Clock), plan, BusSettings.OnDemand, transport.Clock);
    }

    private static string Value(Bus bus, string address)
    {
        bus.TryGetValue(Cpu2, PlcAddress.Parse(address), out var value).Should().BeTrue();
        return $"{Convert.ToHexString(value.Raw.AsSpan())} {value.Quality}";
    }

    /// <summary>The panel's side of the wire, noting each job it sends as "read 1", "write 2" (function and PDU reference).</summary>
    private sealed class JobRecorder(SimulatedLineTransport inner) : ITransport
    {
        private readonly PpiFrameReader _reader = new();

        public SimulatedLineTransport Inner => inner;

        public List<string> Jobs { get; } = [];

        public string Name => inner.Name;

        public bool IsOpen => inner.IsOpen;

        public Task OpenAsync(CancellationToken cancellationToken) => inner.OpenAsync(cancellationToken);

        public Task WriteAsync(ReadOnlyMemory<byte> data, CancellationToken cancellationToken)
        {
            _reader.Append(data.Span);
            while (_reader.TryTake(out var result))
            {
                if (result.Frame is { Kind: PpiFrameKind.Variable, Data: var pdu })
                {
                    var function = pdu[10] switch { 0x04 => "read", 0x05 => "write", var other => $"16#{other:X2}" };
                    Jobs.Add($"{function} {(pdu[4] << 8) | pdu[5]}");
                }
            }

            return inner.WriteAsync(data, cancellationToken);
        }

        public Task<int> ReadAsync(Memory<byte> buffer, TimeSpan timeout, CancellationToken cancellationToken) =>
            inner.ReadAsync(buffer, timeout, cancellationToken);

        public void DiscardInput() => inner.DiscardInput();

        public ValueTask DisposeAsync() => inner.DisposeAsync();
    }
}
