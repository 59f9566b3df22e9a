using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.Simulator.Soak;
using OperatorPanel.TestKit;

namespace OperatorPanel.Simulator.Tests.Soak;

public sealed class ExecutedWriteObserverTests
{
    private readonly PlcMemory _memory = new(CpuProfiles.For(CpuModel.Cpu226));
    private readonly ManualTimeProvider _time = new();

    [Fact]
    public void RunUntil_WritesAtTwoMoments_RecordsEachWithItsChangedBytesInOrder()
    {
        var line = new ScriptedLine(_memory, (TimeSpan.FromMilliseconds(3), 100, [0, 7, 0, 9]), (TimeSpan.FromMilliseconds(8), 102, [5]));
        var observer = new ExecutedWriteObserver(line, _memory, [new WatchedBytes(ProtocolArea.V, 0, 1000)], _time);

        observer.RunUntil(TimeSpan.FromMilliseconds(20));

        observer.Changes.Should().HaveCount(2);
        observer.Changes[0].First.Should().Be(101);
        observer.Changes[0].After.Should().Equal(7, 0, 9);
        observer.Changes[0].Before.Should().Equal(0, 0, 0);
        observer.Changes[1].First.Should().Be(102);
        observer.Changes[1].After.Should().Equal(5);
        observer.Changes[1].Before.Should().Equal(0);
    }

    [Fact]
    public void RunUntil_WriteOutsideTheWatchedBytes_IsNotRecorded()
    {
        var line = new ScriptedLine(_memory, (TimeSpan.FromMilliseconds(3), 2000, [1]));
        var observer = new ExecutedWriteObserver(line, _memory, [new WatchedBytes(ProtocolArea.V, 0, 1000)], _time);

        observer.RunUntil(TimeSpan.FromMilliseconds(20));

        observer.Changes.Should().BeEmpty();
    }

    /// <summary>The field's I setting reaches I through the CPU's copy (here the line's own I) and its SM setting at once; the observer sees both.</summary>
    [Fact]
    public void RunUntil_FieldSetsTheLastInputAndSmBytes_RecordsEachChangeAfterItsSetting()
    {
        var field = new SoakField(new ScriptedLine(_memory), _memory.I, _memory, [new WatchedBytes(ProtocolArea.I, 12, 4), new WatchedBytes(ProtocolArea.SM, 546, 4)], _time);
        var observer = new ExecutedWriteObserver(
            field, _memory, [new WatchedBytes(ProtocolArea.I, 0, 16), new WatchedBytes(ProtocolArea.SM, 546, 4)], _time);

        _time.Advance(TimeSpan.FromSeconds(1));
        observer.RunUntil(SoakField.Period + TimeSpan.FromMilliseconds(2));

        byte[] first = [SoakField.Pattern(1, 12), SoakField.Pattern(1, 13), SoakField.Pattern(1, 14), SoakField.Pattern(1, 15)];
        field.Settings.Select(s => (s.Area, s.First)).Should().Equal((ProtocolArea.I, 12), (ProtocolArea.SM, 546));
        field.Settings[0].After.Should().Equal(first);
        observer.Changes.Select(c => (c.Area, c.First)).Should().Equal((ProtocolArea.I, 12), (ProtocolArea.SM, 546));
        observer.Changes[0].After.Should().Equal(first);
        observer.Changes[0].Timestamp.Should().BeGreaterThanOrEqualTo(field.Settings[0].Timestamp);
    }
}
