using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Hosting;
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

    /// <summary>A line that writes given V bytes when it runs past given times, as an executed WRITE would.</summary>
    private sealed class ScriptedLine(PlcMemory memory, params (TimeSpan At, int Offset, byte[] Bytes)[] writes) : ISimulatedLine
    {
        public TimeSpan Now { get; private set; }

        public int FramesReceived => 0;

        public int Replies => 0;

        public TimeSpan? NextOutput => null;

        public void RunUntil(TimeSpan until)
        {
            foreach (var (at, offset, bytes) in writes.Where(w => w.At > Now && w.At <= until))
            {
                bytes.CopyTo(memory.V, offset);
            }

            Now = until;
        }

        public void Deliver(ReadOnlySpan<byte> characters)
        {
        }

        public byte[] TakeTransmitted() => [];
    }
}
