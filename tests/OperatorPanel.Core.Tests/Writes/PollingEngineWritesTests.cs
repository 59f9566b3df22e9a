using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Tests.Polling;
using OperatorPanel.Core.Transport;
using OperatorPanel.Core.Writes;
using Serilog.Events;
using static OperatorPanel.Core.Tests.Polling.PollingSome;

namespace OperatorPanel.Core.Tests.Writes;

/// <summary>Writes through the engine, executed by <c>RunCycleAsync</c> ahead of its READs.</summary>
public sealed class PollingEngineWritesTests
{
    private readonly PollingTestClock _clock = new();
    private readonly PollingLogSink _log = new();
    private readonly FakePlcLink _link;

    public PollingEngineWritesTests() => _link = new FakePlcLink(_clock);

    [Fact]
    public async Task Write_ReadBackMatches_ConfirmedAndStoreUpdatedAtOnce()
    {
        var changes = new List<ValueChange>();
        var engine = Engine(Items(One, "VW100", "VB101"), changes.AddRange);

        var outcome = await WriteThroughCycle(engine, WriteRequest.Bytes(One, PlcAddress.Parse("VW100"), [0x12, 0x34]));

        outcome.Should().BeEquivalentTo(new WriteOutcome.Confirmed([0x12, 0x34]));
        _link.Memory(One, ProtocolArea.V)[100..102].Should().Equal(0x12, 0x34);
        changes.Take(2).Select(c => (c.Address.ToString(), Convert.ToHexString(c.Current.Raw.AsSpan())))
            .Should().BeEquivalentTo(new[] { ("VW100", "1234"), ("VB101", "34") }, "the read-back is published before the READ");
    }

    [Fact]
    public async Task Write_ReadBackDiffers_ReturnsMismatchAndLogsBothValues()
    {
        _link.Set(One, ProtocolArea.V, 10, 0x00, 0x07);
        var engine = Engine(Items(One, "VW10"));
        await engine.RunCycleAsync(CancellationToken.None);
        _link.IgnoresWrites.Add(One);

        var outcome = await WriteThroughCycle(engine, WriteRequest.Bytes(One, PlcAddress.Parse("VW10"), [0x00, 0x08]));

        outcome.Should().BeEquivalentTo(new WriteOutcome.ReadBackMismatch([0x00, 0x08], [0x00, 0x07]));
        var logged = _log.Events.Single(e => e.MessageTemplate.Text.StartsWith("Write", StringComparison.Ordinal));
        logged.Level.Should().Be(LogEventLevel.Warning);
        logged.RenderMessage().Should().Be("Write station 1 VW10: 16#0007 -> 16#0008 read back 16#0007");
    }

    [Fact]
    public async Task Write_Confirmed_LoggedWithOldAndNewValue()
    {
        _link.Set(One, ProtocolArea.Q, 0, 0x01);
        var engine = Engine(Items(One, "QB0"));
        await engine.RunCycleAsync(CancellationToken.None);

        await WriteThroughCycle(engine, WriteRequest.Bytes(One, PlcAddress.Parse("QB0"), [0x81]));

        var logged = _log.Events.Single(e => e.MessageTemplate.Text.StartsWith("Write", StringComparison.Ordinal));
        logged.Level.Should().Be(LogEventLevel.Information);
        PollingLogSink.Property(logged, "Station").Should().Be(1);
        PollingLogSink.Property(logged, "Address").Should().Be("QB0");
        PollingLogSink.Property(logged, "OldValue").Should().Be("16#01");
        PollingLogSink.Property(logged, "NewValue").Should().Be("16#81");
    }

    [Fact]
    public async Task Write_AddressNeverPolled_LogsOldValueUnknown()
    {
        var engine = Engine(Items(One, "VB0"));

        await WriteThroughCycle(engine, WriteRequest.Bit(One, PlcAddress.Parse("M3.1"), true));

        var logged = _log.Events.Single(e => e.MessageTemplate.Text.StartsWith("Write", StringComparison.Ordinal));
        PollingLogSink.Property(logged, "OldValue").Should().Be("unknown");
        PollingLogSink.Property(logged, "NewValue").Should().Be("1");
    }

    [Fact]
    public async Task Write_Bit_SendsWriteBitAndJudgesTheBitInTheReadBackByte()
    {
        _link.Set(One, ProtocolArea.M, 2, 0b1000_0001);
        var engine = Engine(Items(One, "M2.3", "MB2"));

        var outcome = await WriteThroughCycle(engine, WriteRequest.Bit(One, PlcAddress.Parse("M2.3"), true));

        outcome.Should().BeEquivalentTo(new WriteOutcome.Confirmed([0x01]));
        _link.Requests[0].Should().BeEquivalentTo(new WriteBitRequest(One, _link.Requests[0].Sequence, ProtocolArea.M, 2, 3, true));
        engine.TryGetValue(One, PlcAddress.Parse("MB2"), out var wholeByte).Should().BeTrue();
        wholeByte.Raw.Should().Equal(0b1000_1001);
    }

    [Fact]
    public async Task Write_LinkFailsAndReadBackFailsToo_UnknownAndSentOnlyOnce()
    {
        var engine = Engine(Items(One, "VB0"));
        _link.Fail(One, new PlcCommunicationException(PlcErrorKind.NoAnswer, One, "no answer after 3 tries"));

        var outcome = await WriteThroughCycle(engine, WriteRequest.Bytes(One, PlcAddress.Parse("VB5"), [0x05]));

        outcome.Should().BeEquivalentTo(new WriteOutcome.Unknown(default, "no answer after 3 tries", "the read-back failed too (NoAnswer: no answer after 3 tries)"));
        _link.Requests.OfType<WriteBlockRequest>().Should().ContainSingle();
        engine.GetStationStatus(One).State.Should().Be(StationState.Offline);
        _log.Events.Should().Contain(e => e.Level == LogEventLevel.Warning && PollingLogSink.Property(e, "Detail") is string);
    }

    [Fact]
    public async Task Write_BuggyLinkReturnsNoReply_FailedAndPollingGoesOn()
    {
        var engine = Engine(Items(One, "VB0"));
        _link.RepliesWithNull.Add(One);

        var outcome = await WriteThroughCycle(engine, WriteRequest.Bytes(One, PlcAddress.Parse("VB5"), [0x05]));

        outcome.Should().BeEquivalentTo(new WriteOutcome.Failed("the link returned no reply object for a write to station 1", WriteFailureKind.UnexpectedReply));
        engine.GetStationStatus(One).LastError.Should().Be("unexpected reply to READ V0+1: no reply object");
    }

    [Fact]
    public async Task Write_PlcRefuses_FailedAsRefusedByPlc()
    {
        var engine = Engine(Items(One, "VB0"));
        _link.Refuse(One, ProtocolError.NotWritable);

        var outcome = await WriteThroughCycle(engine, WriteRequest.Bytes(One, PlcAddress.Parse("VB8000"), [0x05]));

        outcome.Should().BeEquivalentTo(new WriteOutcome.Failed("station 1 refused the write: 83: the PLC refuses writes there (inputs, SM, an area the handler's write mask leaves out, or the handler's own V bytes)", WriteFailureKind.RefusedByPlc));
    }

    [Theory]
    [InlineData("IB0", "IB0: inputs are read from the field; the panel never writes them")]
    [InlineData("SB0", "SB0: the Freeport link writes only Q, M and V")]
    [InlineData("SMB34", "SMB34: the Freeport handler does not serve SM")]
    public async Task Write_AreaTheLinkNeverWrites_FailsWithoutSending(string address, string reason)
    {
        var engine = Engine(Items(One, "VB0"));

        var outcome = await WriteThroughCycle(engine, WriteRequest.Bytes(One, PlcAddress.Parse(address), [0x01]));

        outcome.Should().BeOfType<WriteOutcome.Failed>().Which.Kind.Should().Be(WriteFailureKind.InvalidRequest);
        ((WriteOutcome.Failed)outcome).Reason.Should().StartWith(reason);
        _link.Requests.Should().NotContain(r => r is WriteBlockRequest || r is WriteBitRequest);
    }

    [Fact]
    public async Task Write_KnownCpuRefusesTheAddress_FailsWithoutSending()
    {
        var cpus = new Dictionary<Station, CpuProfile> { [One] = CpuProfiles.For(CpuModel.Cpu222) };
        var engine = new PollingEngine(_link, PollPlanner.Build(Items(One, "VB0"), cpus), _clock, _log.CreateLogger());

        var outcome = await WriteThroughCycle(engine, WriteRequest.Bytes(One, PlcAddress.Parse("SMB5"), [0x01]));

        outcome.Should().BeOfType<WriteOutcome.Failed>().Which.Kind.Should().Be(WriteFailureKind.InvalidRequest);
        _link.Requests.Should().NotContain(r => r is WriteBlockRequest || r is WriteBitRequest);
    }

    [Fact]
    public async Task Write_QueuedDuringACycle_GoesAheadOfTheNextRead()
    {
        var engine = Engine([Item(One, "VB0"), Item(Two, "VB0")]);
        Task<WriteOutcome>? write = null;
        _link.OnExchange = request =>
        {
            if (request.Station == One && request is ReadChangesRequest)
            {
                write = engine.WriteAsync(WriteRequest.Bytes(Two, PlcAddress.Parse("VB0"), [0x42]));
            }
        };

        await engine.RunCycleAsync(CancellationToken.None);

        _link.Requests.Select(r => (r.Station.Address, r.Command)).Should().Equal(
            (1, CommandCode.DefineList), (1, CommandCode.ReadChanges), (2, CommandCode.Write), (2, CommandCode.DefineList), (2, CommandCode.ReadChanges));
        (await write!.Guarded()).Should().BeOfType<WriteOutcome.Confirmed>();
        engine.TryGetValue(Two, PlcAddress.Parse("VB0"), out var value).Should().BeTrue();
        value.Raw.Should().Equal(0x42);
    }

    [Fact]
    public async Task Write_WithdrawnBeforeSending_IsNeverSent()
    {
        var engine = Engine(Items(One, "VB0"));
        using var withdraw = new CancellationTokenSource();
        var write = engine.WriteAsync(WriteRequest.Bytes(One, PlcAddress.Parse("VB0"), [0x01]), withdraw.Token);
        await withdraw.CancelAsync();

        await engine.RunCycleAsync(CancellationToken.None);

        write.IsCanceled.Should().BeTrue();
        _link.Requests.Should().NotContain(r => r is WriteBlockRequest || r is WriteBitRequest);
    }

    private PollingEngine Engine(IEnumerable<WatchedItem> items, Action<IReadOnlyList<ValueChange>>? onChanges = null) =>
        new(_link, PollPlanner.Build(items), _clock, _log.CreateLogger(), onChanges: onChanges);

    private static async Task<WriteOutcome> WriteThroughCycle(PollingEngine engine, WriteRequest request)
    {
        var write = engine.WriteAsync(request);
        await engine.RunCycleAsync(CancellationToken.None);
        return await write.Guarded();
    }
}
