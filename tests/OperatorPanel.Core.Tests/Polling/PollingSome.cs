using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;

namespace OperatorPanel.Core.Tests.Polling;

/// <summary>Short builders for the polling and write tests.</summary>
internal static class PollingSome
{
    public static readonly Station One = new(1);
    public static readonly Station Two = new(2);

    public static WatchedItem Item(Station station, string address) => new(station, PlcAddress.Parse(address));

    public static WatchedItem[] Items(Station station, params string[] addresses) => [.. addresses.Select(a => Item(station, a))];

    /// <summary>A guard against a hung test, never a way to wait for time to pass: the engine runs on the test clock.</summary>
    public static Task<T> Guarded<T>(this Task<T> task) => task.WaitAsync(TimeSpan.FromSeconds(10));

    public static Task Guarded(this Task task) => task.WaitAsync(TimeSpan.FromSeconds(10));
}
