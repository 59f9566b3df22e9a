using System.Collections.Immutable;
using System.Globalization;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.TestKit;

/// <summary>
/// An <see cref="ITransport"/> playing an annotated exchange (S7NetPlus's CommunicationSequence idea):
/// <code>
/// // IDENTIFY station 1
/// &gt; "&lt;01" {seq} "01" ?? ?? "&gt;"      // what the PC must write, in one WriteAsync
/// &lt; "&lt;01" {seq} "8100" {bcc} "&gt;"   // what its reads then return (one line = one chunk)
/// &gt; "&lt;01" {seq} "01" ?? ?? "&gt;"      // the retry ...
/// &lt; no response                // ... times out
/// </code>
/// Tokens: hex pairs, "ASCII", ?? (any byte), {name} (captures two bytes in a request, echoes them in a response),
/// {bcc} (protocol block check over the response's characters after '&lt;'). A write that differs from the script
/// throws <see cref="ScriptMismatchException"/> and is remembered, so <see cref="AssertComplete"/> fails the test
/// even when the code under test caught the exception. Reads with nothing to return time out at once; with a
/// <see cref="ManualTimeProvider"/> they first advance it by the read's timeout, as if that time had passed.
/// </summary>
public sealed class ScriptedTransport : ITransport
{
    private readonly ImmutableArray<ScriptStep> _steps;
    private readonly ManualTimeProvider? _clock;
    private readonly Lock _lock = new();
    /// <summary>Response chunks released by matched requests; null = a read that times out.</summary>
    private readonly List<byte[]?> _pending = [];
    private readonly Dictionary<string, byte[]> _captures = [];
    private readonly List<string> _failures = [];
    private readonly List<byte[]> _written = [];
    private int _next;

    public ScriptedTransport(string script, ManualTimeProvider? clock = null, string name = "scripted")
    {
        ArgumentNullException.ThrowIfNull(script);
        _steps = ScriptParser.Parse(script);
        _clock = clock;
        Name = name;
        ReleaseResponses();
    }

    public string Name { get; }

    public bool IsOpen { get; private set; }

    public int DiscardCount { get; private set; }

    /// <summary>Every WriteAsync's bytes, in order.</summary>
    public IReadOnlyList<byte[]> Written
    {
        get
        {
            lock (_lock)
            {
                return [.. _written];
            }
        }
    }

    public Task OpenAsync(CancellationToken cancellationToken)
    {
        IsOpen = true;
        return Task.CompletedTask;
    }

    public Task WriteAsync(ReadOnlyMemory<byte> data, CancellationToken cancellationToken)
    {
        lock (_lock)
        {
            _written.Add(data.ToArray());
            if (_next >= _steps.Length)
            {
                throw Fail($"unexpected write after the script ended: {Hex.Format(data.Span)}");
            }

            var step = _steps[_next];
            if (!ScriptMatcher.TryMatch(step.Elements, data.Span, _captures, out var problem))
            {
                throw Fail($"line {step.LineNumber} expected {step.Text}\n  but the PC wrote {Hex.Format(data.Span)} ({Printable(data.Span)}): {problem}");
            }

            _next++;
            ReleaseResponses();
        }

        return Task.CompletedTask;
    }

    public Task<int> ReadAsync(Memory<byte> buffer, TimeSpan timeout, CancellationToken cancellationToken)
    {
        lock (_lock)
        {
            if (_pending.Count > 0 && _pending[0] is { } chunk)
            {
                var count = Math.Min(buffer.Length, chunk.Length);
                chunk.AsSpan(0, count).CopyTo(buffer.Span);
                if (count < chunk.Length)
                {
                    _pending[0] = chunk[count..];
                }
                else
                {
                    _pending.RemoveAt(0);
                }

                return Task.FromResult(count);
            }

            if (_pending.Count > 0)
            {
                _pending.RemoveAt(0);
            }
        }

        _clock?.Advance(timeout);
        return Task.FromResult(0);
    }

    public void DiscardInput()
    {
        lock (_lock)
        {
            DiscardCount++;
            _pending.Clear();
        }
    }

    /// <summary>Throws when a write went wrong or scripted requests were never written.</summary>
    public void AssertComplete()
    {
        lock (_lock)
        {
            if (_failures.Count > 0)
            {
                throw new ScriptMismatchException(string.Join('\n', _failures));
            }

            if (_next < _steps.Length)
            {
                throw new ScriptMismatchException($"script not finished: line {_steps[_next].LineNumber} ({_steps[_next].Text}) never happened");
            }
        }
    }

    public ValueTask DisposeAsync()
    {
        IsOpen = false;
        return ValueTask.CompletedTask;
    }

    private static string Printable(ReadOnlySpan<byte> data) =>
        new(data.ToArray().Select(b => b is >= 0x20 and < 0x7F ? (char)b : '.').ToArray());

    private void ReleaseResponses()
    {
        while (_next < _steps.Length && _steps[_next].Kind != ScriptStepKind.Request)
        {
            var step = _steps[_next++];
            _pending.Add(step.Kind == ScriptStepKind.NoResponse ? null : ScriptMatcher.Render(step, _captures));
        }
    }

    private ScriptMismatchException Fail(string message)
    {
        var text = string.Create(CultureInfo.InvariantCulture, $"{Name}: {message}");
        _failures.Add(text);
        return new ScriptMismatchException(text);
    }
}
