using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Alarms;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Tests.Projects;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Fuzz;

/// <summary>
/// The alarm history file with flipped bytes and truncations (seeded): loading never throws, and a file it cannot use
/// whole comes back with a message for the operator; a good file loads every entry with no message.
/// </summary>
public sealed class AlarmHistoryFuzzTests : IDisposable
{
    /// <summary>Bytes that break JSON structure, a line, a number, or UTF-8 (16#FF never starts a character).</summary>
    private static readonly byte[] FlipTo = [.. "{}[]\",:0\n\r\0"u8, 0xFF];

    private readonly TempFolder _folder = new();
    private readonly ManualTimeProvider _clock = new();

    public void Dispose() => _folder.Dispose();

    [Fact]
    public void Load_MutatedHistory_NeverThrowsAndExplainsWhatItDropped()
    {
        var path = _folder.File("line.alarms.jsonl");
        var history = new AlarmHistoryFile(path, _clock);
        AlarmEvent[] entries =
        [
            .. Enumerable.Range(0, 8).Select(i => new AlarmEvent(
                _clock.GetUtcNow().AddSeconds(i), "Filler", new Station(2), PlcAddress.ForBit(MemoryArea.M, 10, i % 8),
                (AlarmTransition)(i % 3), AlarmState.ActiveUnacknowledged, AlarmClass.Fault, $"Alarm {i}: Überdruck \"Tank\"")),
        ];
        history.TryAppend(entries, out var error).Should().BeTrue(error);
        var good = File.ReadAllBytes(path);
        history.Load().Should().Match<AlarmHistoryLoad>(l => l.Message == null && l.Events.Length == entries.Length);

        var random = new Random(1107);
        var failures = new List<string>();
        for (var i = 0; i < 300; i++)
        {
            var bytes = (byte[])good.Clone();
            string how;
            if (random.Next(2) == 0)
            {
                var at = random.Next(bytes.Length);
                bytes[at] = FlipTo[random.Next(FlipTo.Length)];
                how = $"byte {at} became {bytes[at]:X2}";
            }
            else
            {
                bytes = bytes[..random.Next(bytes.Length)];
                how = $"cut to {bytes.Length} bytes";
            }

            File.WriteAllBytes(path, bytes);
            try
            {
                var load = history.Load();
                if (load.Events.Length < entries.Length && bytes.Length > 0 && load.Message is null && !bytes.AsSpan().SequenceEqual(good.AsSpan(0, bytes.Length)))
                {
                    failures.Add($"#{i} {how}: {load.Events.Length} of {entries.Length} entries and no message");
                }
            }
            catch (Exception ex) when (ex is not OutOfMemoryException)
            {
                failures.Add($"#{i} {how}: {ex.GetType().Name} {ex.Message}");
            }
        }

        failures.Should().BeEmpty();
    }
}
