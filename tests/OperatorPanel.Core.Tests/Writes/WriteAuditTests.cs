using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Tests.Audit;
using OperatorPanel.Core.Tests.Polling;
using OperatorPanel.Core.Writes;
using static OperatorPanel.Core.Tests.Polling.PollingSome;

namespace OperatorPanel.Core.Tests.Writes;

/// <summary>Every write is on record before it leaves: the engine's intent and outcome entries around the frame.</summary>
public sealed class WriteAuditTests
{
    private readonly PollingTestClock _clock = new();
    private readonly FakePlcLink _link;
    private readonly RecordingTrail _trail = new();

    public WriteAuditTests() => _link = new FakePlcLink(_clock);

    [Fact]
    public async Task Write_WithAudit_IntentIsOnRecordBeforeTheFrameLeavesAndOutcomeBeforeTheCallerHearsIt()
    {
        _link.Set(One, ProtocolArea.V, 100, 0, 0, 0, 0);
        var engine = Engine(Items(One, "VD100"));
        await engine.RunCycleAsync(CancellationToken.None);
        var recordedWhenSent = new List<int>();
        _link.OnExchange = request =>
        {
            if (request is WriteBlockRequest)
            {
                recordedWhenSent.Add(_trail.Entries.Count);
            }
        };

        var write = engine.WriteAsync(WriteRequest.Bytes(One, PlcAddress.Parse("VD100"), [0, 0, 3, 0xE7]) with { Symbol = "FillSetpoint" });
        await engine.RunCycleAsync(CancellationToken.None);
        await write.Guarded();

        recordedWhenSent.Should().Equal([1], "the intent, and only it, was on record when the frame left");
        _trail.Entries.Should().HaveCount(2);
        var (intent, outcome) = (_trail.Entries[0], _trail.Entries[1]);
        intent.Should().BeEquivalentTo(new AuditEntry(
            intent.Id, AuditStep.Intent, AuditAction.Write, PollingTestClock.Start, AuditUser.Current, "COM9", One, "VD100", "FillSetpoint", "16#00000000", "16#000003E7"));
        outcome.Should().BeEquivalentTo(intent with { Step = AuditStep.Outcome, Outcome = "confirmed" });
    }

    [Fact]
    public async Task Write_IntentCannotBeRecorded_IsNotSentAndSaysWhy()
    {
        _trail.Refuse = "the disk is full";
        var engine = Engine(Items(One, "VB0"));

        var write = engine.WriteAsync(WriteRequest.Bytes(One, PlcAddress.Parse("VB0"), [7]));
        await engine.RunCycleAsync(CancellationToken.None);
        var outcome = await write.Guarded();

        outcome.Should().BeEquivalentTo(new WriteOutcome.Failed("the write was not sent: it could not be put on record (the disk is full)", WriteFailureKind.NotRecorded));
        _link.Requests.Should().NotContain(r => r is WriteBlockRequest);
        _link.Memory(One, ProtocolArea.V)[0].Should().Be(0);
    }

    private PollingEngine Engine(IEnumerable<WatchedItem> items) =>
        new(_link, PollPlanner.Build(items), _clock) { Audit = new AuditContext(_trail, "COM9", AuditUser.Current) };
}
