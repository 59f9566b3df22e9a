using Microsoft.Data.Sqlite;
using OperatorPanel.Core.Polling;
using OperatorPanel.Historian.Recording;
using OperatorPanel.Historian.Storage;
using Serilog.Core;
using static OperatorPanel.Historian.Tests.HistoryFixture;

namespace OperatorPanel.Historian.Tests.Recording;

/// <summary>The background writer: the database it makes, and what a locked database, a full disk or a newer schema do.</summary>
public sealed class HistoryWriterTests
{
    [Fact]
    public async Task Flush_NewDatabase_IsWalWithTheCurrentSchemaAndOneOpenSession()
    {
        await using var history = new HistoryFixture();
        using var recording = history.Record();

        await history.Historian.FlushAsync();

        history.Scalar("PRAGMA user_version").Should().Be(HistorySchema.Version);
        history.Scalar("SELECT count(*) FROM sessions WHERE ended IS NULL AND source = 'test'").Should().Be(1);
        using var connection = new SqliteConnection($"Data Source={history.DatabasePath};Pooling=False");
        connection.Open();
        using var mode = connection.CreateCommand();
        mode.CommandText = "PRAGMA journal_mode";
        mode.ExecuteScalar().Should().Be("wal");
    }

    [Fact]
    public async Task Dispose_ClosesTheSessionWithItsEnd()
    {
        var history = new HistoryFixture();
        var path = history.DatabasePath;
        var copy = path + ".copy";
        using (history.Record())
        {
            await history.Historian.FlushAsync();
        }

        await history.Historian.DisposeAsync();
        File.Copy(path, copy);
        using var connection = new SqliteConnection($"Data Source={copy};Mode=ReadOnly;Pooling=False");
        connection.Open();
        using var command = connection.CreateCommand();
        command.CommandText = "SELECT count(*) FROM sessions WHERE ended IS NOT NULL";
        ((long)command.ExecuteScalar()!).Should().Be(1);
        connection.Close();
        await history.DisposeAsync();
    }

    [Fact]
    public async Task Store_DatabaseLockedByAnotherWriter_ReportsOnceKeepsTheRowsAndStoresThemWhenFree()
    {
        await using var history = new HistoryFixture();
        using var recording = history.Record();
        await history.Historian.FlushAsync();
        var reports = 0;
        history.Historian.ProblemChanged += (_, _) => reports++;

        using (var other = new SqliteConnection($"Data Source={history.DatabasePath};Pooling=False"))
        {
            other.Open();
            using var hold = other.BeginTransaction(deferred: false);
            using (var write = other.CreateCommand())
            {
                write.Transaction = hold;
                write.CommandText = "INSERT INTO meta (key, value) VALUES ('other', 'writer')";
                write.ExecuteNonQuery();
            }

            history.Publish(Level, "0064");
            await history.Historian.FlushAsync();
            history.Publish(Level, "00C8");
            await history.Historian.FlushAsync();

            history.Historian.Problem.Should().Contain("locked by another program");
            reports.Should().Be(1);
            hold.Rollback();
        }

        var values = (await history.SamplesAsync(Level)).Select(s => s.Stored);

        values.Should().Equal(null, 100, 200);
        history.Historian.Problem.Should().BeNull();
        history.Historian.Lost.Should().Be(0);
        reports.Should().Be(2, "once when it failed, once when it recovered");
    }

    [Fact]
    public async Task Store_DiskFull_ReportsItAndTheLineGoesOn()
    {
        // A page limit makes SQLite answer SQLITE_FULL, as a full disk does.
        await using var history = new HistoryFixture(onOpened: c => HistoryDatabase.Execute(c, "PRAGMA max_page_count = 12"));
        using var recording = history.Record();
        for (var i = 0; i < 3000; i++)
        {
            history.Publish(Level, (i * 100 % 65536).ToString("X4", System.Globalization.CultureInfo.InvariantCulture));
            history.Time.Advance(TimeSpan.FromMilliseconds(10));
        }

        await history.Historian.FlushAsync();

        history.Historian.Problem.Should().Contain("the disk is full");
        // The writer's loop may store a first small batch before the pages run out (it wakes while the clock moves).
        history.Historian.Written.Should().BeLessThan(3000, "what did not fit is kept for a retry, not counted as written");
    }

    [Fact]
    public async Task Enqueue_QueueFull_CountsTheLostRowsAndNeverBlocks()
    {
        var folder = Path.Combine(Path.GetTempPath(), "opanel-history-tests-" + Guid.NewGuid().ToString("N"));
        var time = new TestKit.ManualTimeProvider();
        await using var writer = new HistoryWriter(Path.Combine(folder, "q.history.db"), Core.Projects.HistorySettings.Default, time, Logger.None, "test");
        var tag = new RecordedTag(Station, Level, "Level", Core.Projects.DisplayFormat.Signed, null);
        await writer.FlushAsync(); // the loop now waits for its period, which the manual clock never reaches

        var accepted = Enumerable.Range(0, HistoryWriter.MaxPending + 5).Count(i => writer.Enqueue(new SampleRow(tag, time.GetUtcNow().AddMilliseconds(i), i, ValueQuality.Good)));

        accepted.Should().BeLessThanOrEqualTo(HistoryWriter.MaxPending);
        writer.Lost.Should().Be(HistoryWriter.MaxPending + 5 - accepted);
        await writer.FlushAsync();
        await writer.DisposeAsync();
        Directory.Delete(folder, recursive: true);
    }

    [Fact]
    public async Task Open_DatabaseOfANewerProgram_IsNeverWritten()
    {
        var folder = Path.Combine(Path.GetTempPath(), "opanel-history-tests-" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(folder);
        var path = Path.Combine(folder, "newer.history.db");
        using (var connection = new SqliteConnection($"Data Source={path};Pooling=False"))
        {
            connection.Open();
            HistoryDatabase.Execute(connection, "CREATE TABLE future (x); PRAGMA user_version = 99;");
        }

        var project = CreateProject(Core.Projects.HistorySettings.Default);
        var time = new TestKit.ManualTimeProvider();
        await using (var historian = Historian.Open(path, project, time, new WriterTuning(TimeSpan.Zero)))
        {
            var stop = new Core.Audit.AuditEntry(Guid.NewGuid(), Core.Audit.AuditStep.Intent, Core.Audit.AuditAction.Stop, time.GetUtcNow(), "tester", "COM3", Station, null, null, "RUN", "STOP");
            (await historian.Audit.RecordAsync(stop, CancellationToken.None)).Should().BeNull("a historian never refuses: its problem is reported once");
            await historian.FlushAsync();

            historian.Problem.Should().Contain("newer Operator Panel");
            historian.Lost.Should().Be(1);
        }

        Directory.Delete(folder, recursive: true);
    }
}
