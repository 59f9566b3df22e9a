using OperatorPanel.Core.Transport;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Transport;

public sealed class BoundedCloseTests
{
    private readonly ManualTimeProvider _clock = new();

    [Fact]
    public async Task RunAsync_CloseBlocksForever_ReturnsAbandonedAfterTheLimit()
    {
        var never = new TaskCompletionSource();

        var run = BoundedClose.RunAsync(() => never.Task, BoundedClose.Limit, _clock);
        _clock.Advance(BoundedClose.Limit - TimeSpan.FromMilliseconds(1));
        run.IsCompleted.Should().BeFalse("the limit has not passed");
        _clock.Advance(TimeSpan.FromMilliseconds(1));

        (await run).Should().BeFalse();
        BoundedClose.Limit.Should().Be(TimeSpan.FromSeconds(2));
    }

    [Fact]
    public async Task RunAsync_CloseFinishes_ReturnsClosedWithoutWaitingForTheLimit()
    {
        (await BoundedClose.RunAsync(() => Task.CompletedTask, BoundedClose.Limit, _clock)).Should().BeTrue();
        _clock.ActiveTimers.Should().Be(0, "the time limit's timer is stopped");
    }
}
